// What the attack tests share: a host on a free loopback port with a join code, a seated raw
// peer, and a fake host (a listener the test speaks for) to set against a real joiner.
#pragma once

#include <gtest/gtest.h>

#include <SFML/Network/TcpListener.hpp>
#include <memory>
#include <string>

#include "net/handshake.hpp"
#include "net/hostile_messages.hpp"
#include "net/live_host.hpp"
#include "net/raw_peer.hpp"

namespace nineball::net_test {

#ifdef NINEBALL_SANITIZED
constexpr double kAttackBound = 30.0;
constexpr double kPromptly = 15.0;  // s: a silent socket's hold, a joiner let in
constexpr double kCtrlC = 5.0;      // s: from Ctrl-C to the joiner's end
#else
constexpr double kAttackBound = 8.0;
constexpr double kPromptly = 4.0;
constexpr double kCtrlC = 1.0;
#endif

inline json helloWith(const std::string& code, const std::string& token = "",
                      const std::string& player = "human", const std::string& name = "Eve") {
  json h = goodHello(name, token);
  h["code"] = code;
  h["player"] = player;
  return h;
}

// A host whose seat A is played from `script` (a match script), with the test's code.
inline net::OnlineRackOptions hostOf(unsigned short port, const std::string& script) {
  net::OnlineRackOptions host;
  host.side = net::Side::Host;
  host.address = {"127.0.0.1", port};
  host.script = scriptOf(script);
  host.match = net::matchPart(json::parse(script));
  host.code = kCode;
  host.wait_s = 4 * kAttackBound;
  host.rejoin_s = 4 * kAttackBound;
  host.limits.silence_s = 1.0;
  host.limits.ping_s = 0.1;
  return host;
}

inline bool connectSoon(RawPeer& peer, unsigned short port) {
  const double deadline = now() + kAttackBound;
  while (!peer.connect(port, 1.0)) {
    if (now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// A seated raw peer's welcome, and every message after it up to the first hash.
struct Seating {
  json welcome;
  std::vector<json> after;
};

// Says `hello` and reads the welcome; with `until_hash`, on to the host's first hash.
inline std::optional<Seating> sitDown(RawPeer& peer, const json& hello, bool until_hash) {
  if (!peer.send(hello)) return std::nullopt;
  Seating s;
  const double deadline = now() + 4 * kAttackBound;
  while (now() < deadline) {
    const json m = peer.next(deadline - now());
    if (m.is_null()) return std::nullopt;
    const std::string type = m.value("type", "");
    if (type == "refuse") return std::nullopt;
    if (type == "welcome") {
      s.welcome = m;
      if (!until_hash) return s;
      continue;
    }
    s.after.push_back(m);
    if (type == "hash") return s;
  }
  return std::nullopt;
}

// One link the test speaks for, its messages read in order.
struct FakeLink {
  std::unique_ptr<net::Connection> link;
  std::deque<json> held;

  // The next message other than a ping, bounded; null when none came.
  json next(double timeout_s) {
    const double deadline = now() + timeout_s;
    while (held.empty() && now() < deadline && !link->closed()) {
      for (auto& j : link->pump(now())) held.push_back(std::move(j));
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (held.empty()) return nullptr;
    json j = std::move(held.front());
    held.pop_front();
    return j;
  }
  void send(const net::Message& m) { link->send(net::toJson(m)); }
};

// A listener the test speaks for as the host.
class FakeHost {
 public:
  explicit FakeHost(unsigned short port) {
    listener_.listen(port);
    listener_.setBlocking(false);
  }
  // The joiner's link, once it has connected (bounded); no link when none came.
  FakeLink accept(double timeout_s) {
    const double deadline = now() + timeout_s;
    while (now() < deadline) {
      auto socket = std::make_unique<sf::TcpSocket>();
      if (listener_.accept(*socket) == sf::Socket::Done) {
        return {std::make_unique<net::Connection>(std::move(socket), now()), {}};
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return {};
  }
  // The joiner's link as raw bytes, once it has connected (bounded); false when none came.
  bool acceptInto(RawPeer& peer, double timeout_s) {
    for (const double deadline = now() + timeout_s; now() < deadline;) {
      if (peer.acceptFrom(listener_)) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  }

 private:
  sf::TcpListener listener_;
};

}  // namespace nineball::net_test
