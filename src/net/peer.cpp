#include "net/peer.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

#include "common/log.hpp"
#include "net/handshake.hpp"

namespace nineball::net {
namespace {

// How long a refusal may take to go out.
constexpr double kFlushSeconds = 0.5;
// The least time a hello's answer is awaited (welcome_within_wait).
constexpr double kLeastWelcomeSeconds = 0.5;

bool isGreeting(const Message& m) {
  return std::holds_alternative<Hello>(m) || std::holds_alternative<Welcome>(m) ||
         std::holds_alternative<Refuse>(m) || std::holds_alternative<Bye>(m);
}

}  // namespace

std::unique_ptr<Peer> Peer::start(const PeerConfig& config, std::string& why) {
  std::unique_ptr<Peer> peer(new Peer(config));
  if (config.side == Side::Host) {
    peer->listener_ = Listener::open(config.address.port, why);
    if (!peer->listener_) return nullptr;
    if (peer->config_.code.empty()) peer->config_.code = makeJoinCode();
    peer->gate_ = std::make_unique<HostGate>(peer->config_.code, config.limits, config.gate);
  }
  return peer;
}

Peer::Peer(const PeerConfig& config) : config_(config) {
  waiting_since_ = now();
}

Peer::~Peer() {
  if (link_ && !link_->closed()) link_->close("closed");
}

std::string Peer::seatToken() const {
  return gate_ ? gate_->seatToken() : std::string();
}

std::string Peer::buildRefusal() const {
  return gate_ ? gate_->buildRefusal() : std::string();
}

double Peer::rejoinLeft() const {
  return config_.rejoin_s - (now() - lost_at_);
}

std::vector<PeerEvent> Peer::poll(bool admit) {
  std::vector<PeerEvent> out;
  if (stage_ == Stage::Over) {
    refuseLate();
    return out;
  }
  if (config_.side == Side::Host) {
    hostStep(admit, out);
  } else if (!link_) {
    joinerStep(out);
  }
  if (!link_) {
    timeouts(out);
    return out;
  }
  readLink(out);
  return out;
}

// Whoever comes once the game is over (the friend's restarted window) hears why, and does
// not hang.
void Peer::refuseLate() {
  while (listener_) {
    auto socket = listener_->accept();
    if (!socket) break;
    Connection c(std::move(socket), now(), config_.limits);
    refuseLink(c, "the game is over: " + over_why_);
  }
}

// The host hears everyone who connects through the gate, in every stage: a friend with the
// code takes the free seat, the seated player with its token takes it back (its old link
// dead, or its program restarted), anyone else is refused by name, silent ones dropped. The
// one let in is linked only when the driver admits (the window: between shots, so that the
// welcome holds every turn played); a later one let in meanwhile takes its place.
void Peer::hostStep(bool admit, std::vector<PeerEvent>& out) {
  if (!gate_) return;
  if (auto admitted = gate_->poll(*listener_, now())) {
    if (admitted_) admitted_->link->close("the other player connected again");
    admitted_ = std::move(admitted);
  }
  if (!admitted_ || !admit) return;
  if (link_) {
    link_->close("the other player connected again");
    link_.reset();
  }
  linkUp(std::move(admitted_->link));
  out.push_back(PeerJoined{admitted_->hello});
  admitted_.reset();
}

void Peer::joinerStep(std::vector<PeerEvent>& out) {
  if (connecting_.valid()) {
    if (connecting_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    ConnectAttempt attempt = connecting_.get();
    if (attempt.socket) {
      linkUp(std::make_unique<Connection>(std::move(attempt.socket), now(), config_.limits));
    } else {
      problem_ = attempt.why;
      next_attempt_ = now() + config_.retry_s;
      out.push_back(PeerUnreachable{attempt.why});
    }
    return;
  }
  if (now() < next_attempt_) return;
  const Address address = config_.address;
  const double timeout = config_.connect_s;
  // connectTo blocks up to its timeout: on a worker, so that the driver's steps go on.
  connecting_ = std::async(std::launch::async, [address, timeout] {
    ConnectAttempt a;
    a.socket = connectTo(address, timeout, a.why);
    return a;
  });
}

void Peer::linkUp(std::unique_ptr<Connection> link) {
  link_ = std::move(link);
  logger("net")->info("linked with {}", link_->remote());
  if (stage_ != Stage::Lost) stage_ = Stage::Handshake;
  handshaking_ = true;
  if (config_.side == Side::Joiner) {
    send(config_.hello);
    answered_ = false;
    double limit = config_.welcome_s;
    if (config_.welcome_within_wait) {
      const double left = stage_ == Stage::Lost  ? rejoinLeft()
                          : config_.wait_s > 0.0 ? config_.wait_s - (now() - waiting_since_)
                                                 : limit;
      limit = std::clamp(left, kLeastWelcomeSeconds, limit);
    }
    welcome_by_ = now() + limit;
  }
}

void Peer::readLink(std::vector<PeerEvent>& out) {
  for (const nlohmann::json& j : link_->pump(now())) {
    std::string why;
    std::optional<Message> message = readMessage(j, why);
    if (!message) {
      out.push_back(PeerBadMessage{why});
      return;
    }
    answered_ = true;
    out.push_back(PeerMessage{std::move(*message)});
  }
  if (link_->closed()) {
    const std::string reason = link_->reason();
    lose(reason);
    out.push_back(PeerLost{problem_});
    return;
  }
  if (config_.side == Side::Joiner && handshaking_ && !answered_ && now() > welcome_by_) {
    // A host that says nothing to the hello (it is over, or not a nineball): said, not hung on.
    link_->close("no welcome");
    lose(link_->reason(), true);
    out.push_back(PeerTimedOut{PeerTimedOut::What::NoWelcome});
  }
}

void Peer::timeouts(std::vector<PeerEvent>& out) {
  const double t = now();
  if (stage_ == Stage::Lost && t - lost_at_ > config_.rejoin_s) {
    timedOut(PeerTimedOut::What::NoRejoin, out);
  } else if (stage_ == Stage::Waiting && config_.wait_s > 0.0 &&
             t - waiting_since_ > config_.wait_s) {
    timedOut(PeerTimedOut::What::NobodyCame, out);
  }
}

void Peer::timedOut(PeerTimedOut::What what, std::vector<PeerEvent>& out) {
  stage_ = Stage::Over;
  out.push_back(PeerTimedOut{what});
}

void Peer::lose(std::string reason, bool retry_later) {
  reason = cleanText(reason, std::string::npos);
  logger("net")->warn("link lost: {}", reason);
  link_.reset();
  handshaking_ = false;
  problem_ = reason;
  if (retry_later) next_attempt_ = now() + config_.retry_s;
  if (!begun_) {
    // Lost before the rack began: wait (or try) again from the start.
    if (stage_ != Stage::Lost) stage_ = Stage::Waiting;
    return;
  }
  if (stage_ != Stage::Lost) {
    stage_ = Stage::Lost;
    lost_at_ = now();
  }
}

void Peer::send(const Message& message) {
  if (!link_ || link_->closed()) return;
  if (!isGreeting(message) && (handshaking_ || stage_ != Stage::Playing)) return;
  link_->send(toJson(message));
}

void Peer::handshakeDone() {
  handshaking_ = false;
  begun_ = true;
  if (stage_ != Stage::Over) stage_ = Stage::Playing;
}

void Peer::refuseNewcomer(const std::string& why) {
  send(Refuse{why});
  if (link_) {
    link_->pump(now());
    link_->flush(kFlushSeconds);
  }
  link_.reset();
  handshaking_ = false;
  if (stage_ == Stage::Handshake) stage_ = Stage::Waiting;  // waiting on for the friend
}

void Peer::drop(const std::string& reason) {
  if (!link_) return;
  link_->close(reason);
  link_.reset();
}

void Peer::closeLink(const std::string& reason) {
  if (link_) link_->close(reason);
}

void Peer::flush(double seconds) {
  if (link_) link_->flush(seconds);
}

void Peer::awaitClose(double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (link_ && !link_->closed() && std::chrono::steady_clock::now() < until) {
    link_->pump(now());
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

void Peer::end(const std::string& why) {
  stage_ = Stage::Over;
  over_why_ = why;
}

void Peer::leave(const std::optional<Bye>& bye, const std::string& reason) {
  if (link_ && !link_->closed()) {
    if (bye) send(*bye);
    link_->pump(now());
    link_->flush(kFlushSeconds);
    link_->close(reason);
  }
  link_.reset();
  stage_ = Stage::Over;
}

}  // namespace nineball::net
