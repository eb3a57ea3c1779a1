// A peer for the protocol fuzz that speaks bytes, not the protocol: it sends whatever it is
// given (framed or not) and waits, never longer than a deadline, for the host's answer.
#pragma once

#include <SFML/Network/IpAddress.hpp>
#include <SFML/Network/TcpListener.hpp>
#include <SFML/Network/TcpSocket.hpp>
#include <algorithm>
#include <chrono>
#include <deque>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "net/wire.hpp"

namespace nineball::net_test {

inline double now() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

/// What a hostile peer heard after what it sent.
struct Answer {
  enum class Kind { Refused, Closed, Timeout };
  Kind kind = Kind::Timeout;
  std::string reason;              ///< the refuse message's reason
  double seconds = 0.0;            ///< from the wait's start to the answer
  std::vector<std::string> heard;  ///< types of the other messages heard meanwhile
  bool closed_after_refusal = false;
  bool heard_type(const std::string& t) const {
    for (const auto& h : heard) {
      if (h == t) return true;
    }
    return false;
  }
};

class RawPeer {
 public:
  /// Connects to the host on this machine's loopback.
  bool connect(unsigned short port, double timeout_s) {
    if (socket_.connect(sf::IpAddress::LocalHost, port,
                        sf::seconds(static_cast<float>(timeout_s))) != sf::Socket::Done) {
      return false;
    }
    socket_.setBlocking(false);
    return true;
  }

  /// Takes the next connection waiting on `listener` (a fake host's side of a link).
  bool acceptFrom(sf::TcpListener& listener) {
    if (listener.accept(socket_) != sf::Socket::Done) return false;
    socket_.setBlocking(false);
    return true;
  }

  /// Sends the bytes as they are, within `timeout_s`; false once the host has closed (or the
  /// deadline passed with bytes unsent).
  bool sendRaw(const std::string& bytes, double timeout_s = 5.0) {
    const double deadline = now() + timeout_s;
    std::size_t at = 0;
    while (at < bytes.size() && !closed_) {
      std::size_t sent = 0;
      const sf::Socket::Status s = socket_.send(bytes.data() + at, bytes.size() - at, sent);
      at += sent;
      if (s == sf::Socket::Disconnected || s == sf::Socket::Error) closed_ = true;
      if (at < bytes.size() && !closed_) {
        if (now() > deadline) return false;
        poll();  // the host may be answering while we send: read it, so neither side stalls
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      }
    }
    return !closed_;
  }
  bool send(const nlohmann::json& message) { return sendRaw(net::framed(message.dump())); }

  /// Reads whatever has arrived.
  void poll() {
    char chunk[65536];
    while (!closed_) {
      std::size_t got = 0;
      const sf::Socket::Status s = socket_.receive(chunk, sizeof chunk, got);
      if (s == sf::Socket::NotReady) return;
      if (s != sf::Socket::Done) {
        closed_ = true;
        return;
      }
      const double t = now();
      if (last_heard_ > 0.0) longest_quiet_ = std::max(longest_quiet_, t - last_heard_);
      last_heard_ = t;
      std::string why;
      if (!reader_.feed(chunk, got, why)) {
        bad_frames_ = true;  // the host sent what is not a message stream: the test fails
        closed_ = true;
        return;
      }
      while (auto text = reader_.next()) {
        nlohmann::json j = nlohmann::json::parse(*text, nullptr, false);
        if (j.is_discarded() || !j.is_object()) {
          bad_frames_ = true;
          continue;
        }
        if (j.value("type", "") != "ping") inbox_.push_back(std::move(j));
      }
    }
  }

  /// The next message other than a ping, within `timeout_s`; null once closed or at the
  /// deadline.
  nlohmann::json next(double timeout_s, bool keep_alive = true) {
    const double deadline = now() + timeout_s;
    while (true) {
      poll();
      if (!inbox_.empty()) {
        nlohmann::json j = std::move(inbox_.front());
        inbox_.pop_front();
        return j;
      }
      if (closed_ || now() > deadline) return nullptr;
      if (keep_alive) keepAlive();
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }

  /// Waits for the host to refuse what was sent: a refuse message, or the link closed. With
  /// `keep_alive` the peer pings meanwhile, so only a refusal closes the link, not the host's
  /// silence timeout.
  Answer awaitRefusal(double timeout_s, bool keep_alive) {
    Answer a;
    const double start = now();
    while (true) {
      poll();
      while (!inbox_.empty()) {
        nlohmann::json j = std::move(inbox_.front());
        inbox_.pop_front();
        const std::string type = j.value("type", "");
        if (type == "refuse") {
          a.kind = Answer::Kind::Refused;
          a.reason = j.value("reason", "");
          a.seconds = now() - start;
          // A refused peer is disconnected too: the link must close after the refusal.
          while (!closed_ && now() - start <= timeout_s) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
            poll();
          }
          a.closed_after_refusal = closed_;
          return a;
        }
        a.heard.push_back(type);
      }
      if (closed_) {
        a.kind = Answer::Kind::Closed;
        a.seconds = now() - start;
        return a;
      }
      if (now() - start > timeout_s) {
        a.kind = Answer::Kind::Timeout;
        a.seconds = now() - start;
        return a;
      }
      if (keep_alive) keepAlive();
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }

  /// A ping now and then, so the host does not drop the link for silence.
  void keepAlive() {
    if (now() - last_ping_ < 0.05) return;
    last_ping_ = now();
    sendRaw(net::framed(R"({"type":"ping"})"), 1.0);
  }

  bool closed() const { return closed_; }
  /// The longest time between two arrivals from the host since the last resetQuiet() (the host
  /// pings every LinkLimits::ping_s when it has nothing else to say).
  double longestQuiet() const { return longest_quiet_; }
  void resetQuiet() {
    poll();
    longest_quiet_ = 0.0;
    last_heard_ = now();
  }
  /// The host sent bytes that are not framed JSON objects.
  bool badFrames() const { return bad_frames_; }

 private:
  sf::TcpSocket socket_;
  net::FrameReader reader_;
  std::deque<nlohmann::json> inbox_;
  bool closed_ = false;
  bool bad_frames_ = false;
  double last_ping_ = 0.0;
  double last_heard_ = 0.0;
  double longest_quiet_ = 0.0;
};

}  // namespace nineball::net_test
