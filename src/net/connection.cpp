#include "net/connection.hpp"

#include <SFML/Network/IpAddress.hpp>
#include <SFML/System/Time.hpp>
#include <chrono>
#include <thread>

#include "common/log.hpp"
#include "io/json_reader.hpp"
#include "net/protocol.hpp"

namespace nineball::net {
namespace {

// Messages are flat records of a few levels; anything deeper is not one of ours.
constexpr int kMostDepth = 16;
// Bytes read per pump at most, so a fast sender cannot hold the game loop.
constexpr std::size_t kMostReadPerPump = 4 * kMaxMessageBytes;
// How long a refusal for a broken stream may take to go out before the link closes.
constexpr double kRefusalFlushSeconds = 0.2;

bool tooDeep(const std::string& text) {
  int depth = 0;
  bool in_string = false;
  bool escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') in_string = true;
    if (c == '[' || c == '{') {
      if (++depth > kMostDepth) return true;
    }
    if (c == ']' || c == '}') --depth;
  }
  return false;
}

}  // namespace

std::optional<nlohmann::json> parseMessage(const std::string& text, std::string& why) {
  if (tooDeep(text)) {
    why = "a message nested more than " + std::to_string(kMostDepth) + " levels deep";
    return std::nullopt;
  }
  try {
    nlohmann::json j = io::readJson(text);
    if (!j.is_object() || !j.contains("type") || !j["type"].is_string()) {
      why = "a message that is not an object with a \"type\"";
      return std::nullopt;
    }
    return j;
  } catch (const io::ParseError& e) {
    // The parser quotes the bytes it stopped at: cleaned, as anything a peer sends.
    why = "a message that is not JSON (" + cleanText(e.message, 120) + ")";
    return std::nullopt;
  }
}

Connection::Connection(std::unique_ptr<sf::TcpSocket> socket, double now, LinkLimits limits)
    : socket_(std::move(socket)),
      limits_(limits),
      last_heard_(now),
      last_said_(now),
      window_start_(now) {
  socket_->setBlocking(false);
  address_ = socket_->getRemoteAddress().toString();
  remote_ = address_ + ":" + std::to_string(socket_->getRemotePort());
}

Connection::~Connection() {
  if (socket_) socket_->disconnect();
}

std::string Connection::remote() const {
  return remote_;
}

void Connection::close(const std::string& reason) {
  if (closed_) return;
  closed_ = true;
  // Often the peer's own words: logged and shown, so cleaned as all peer text is.
  reason_ = cleanText(reason, std::string::npos);
  logger("net")->info("link to {} closed: {}", remote_, reason_);
  socket_->disconnect();
}

void Connection::refuseAndClose(const std::string& what_it_did) {
  if (closed_) return;
  // The peer hears why before the link closes (as every refusal), bounded: the stream it
  // sent is broken, but it may still read.
  unsent_ += framed(
      nlohmann::json{{"type", "refuse"}, {"reason", cleanText("disconnected: you " + what_it_did)}}
          .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  flush(kRefusalFlushSeconds);
  close("the other side " + what_it_did);
}

void Connection::send(const nlohmann::json& message) {
  if (closed_) return;
  unsent_ += framed(message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  if (unsent_.size() > limits_.most_unsent) close("the other side stopped reading");
}

void Connection::sendQueued() {
  while (!closed_ && !unsent_.empty()) {
    std::size_t sent = 0;
    const sf::Socket::Status s = socket_->send(unsent_.data(), unsent_.size(), sent);
    unsent_.erase(0, sent);
    if (s == sf::Socket::Done || s == sf::Socket::Partial) {
      if (sent == 0) return;
      continue;
    }
    if (s == sf::Socket::NotReady) return;
    close(s == sf::Socket::Disconnected ? "the other side closed the connection"
                                        : "the connection failed");
  }
}

void Connection::flush(double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  sendQueued();
  while (!closed_ && !unsent_.empty() && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    sendQueued();
  }
}

bool Connection::accept(const std::string& text, double now, nlohmann::json& out) {
  if (now - window_start_ >= 1.0) {
    window_start_ = now;
    window_count_ = 0;
  }
  if (++window_count_ > limits_.messages_per_second) {
    refuseAndClose("flooded the link (more than " + std::to_string(limits_.messages_per_second) +
                   " messages a second)");
    return false;
  }
  std::string why;
  auto message = parseMessage(text, why);
  if (!message) {
    refuseAndClose("sent " + why);
    return false;
  }
  out = std::move(*message);
  return true;
}

void Connection::receive(double now, std::vector<nlohmann::json>& out) {
  char chunk[16384];
  std::size_t total = 0;
  while (!closed_ && total < kMostReadPerPump) {
    std::size_t got = 0;
    const sf::Socket::Status s = socket_->receive(chunk, sizeof chunk, got);
    if (s == sf::Socket::NotReady) break;
    if (s != sf::Socket::Done && s != sf::Socket::Partial) {
      close(s == sf::Socket::Disconnected ? "the other side closed the connection"
                                          : "the connection failed");
      break;
    }
    if (got == 0) break;
    total += got;
    std::string why;
    if (!reader_.feed(chunk, got, why)) {
      refuseAndClose("sent " + why);
      break;
    }
    while (auto text = reader_.next()) {
      // Only a whole message is a sign of life: a frame dripped a byte at a time is not.
      last_heard_ = now;
      nlohmann::json message;
      if (!accept(*text, now, message)) break;
      if (message["type"] != "ping") out.push_back(std::move(message));
    }
  }
}

std::vector<nlohmann::json> Connection::pump(double now) {
  std::vector<nlohmann::json> out;
  if (closed_) return out;
  if (now - last_said_ >= limits_.ping_s) {
    send({{"type", "ping"}});
  }
  if (!unsent_.empty()) last_said_ = now;
  // Read first: what the peer sent before it closed is still to be had after a failed send.
  receive(now, out);
  sendQueued();
  if (!closed_ && now - last_heard_ > limits_.silence_s) {
    close("the other side stopped answering (nothing for " +
          std::to_string(static_cast<int>(limits_.silence_s)) + " s)");
  }
  return out;
}

std::unique_ptr<Listener> Listener::open(unsigned short port, std::string& why) {
  auto l = std::make_unique<Listener>();
  if (l->listener_.listen(port) != sf::Socket::Done) {
    why = "cannot listen on port " + std::to_string(port) + " (in use, or below 1024 without root)";
    return nullptr;
  }
  l->listener_.setBlocking(false);
  return l;
}

std::unique_ptr<sf::TcpSocket> Listener::accept() {
  auto socket = std::make_unique<sf::TcpSocket>();
  if (listener_.accept(*socket) != sf::Socket::Done) return nullptr;
  return socket;
}

unsigned short Listener::port() const {
  return listener_.getLocalPort();
}

std::unique_ptr<sf::TcpSocket> connectTo(const Address& address, double timeout_s,
                                         std::string& why) {
  const sf::IpAddress ip(address.host);
  if (ip == sf::IpAddress::None) {
    why = "cannot find the host \"" + address.host + "\"";
    return nullptr;
  }
  auto socket = std::make_unique<sf::TcpSocket>();
  if (socket->connect(ip, address.port, sf::seconds(static_cast<float>(timeout_s))) !=
      sf::Socket::Done) {
    why = "nobody answers at " + addressText(address);
    return nullptr;
  }
  return socket;
}

std::string localAddress() {
  return sf::IpAddress::getLocalAddress().toString();
}

}  // namespace nineball::net
