#include "net/host_gate.hpp"

#include <algorithm>
#include <cmath>

#include "common/log.hpp"
#include "net/handshake.hpp"

namespace nineball::net {
namespace {

constexpr char kBusy[] = "busy: ";

}  // namespace

bool isBusyRefusal(const std::string& reason) {
  return reason.rfind(kBusy, 0) == 0;
}

void refuseLink(Connection& c, const std::string& why) {
  if (c.closed()) return;
  c.send(toJson(Refuse{why}));
  c.flush(0.5);
  c.close(cleanText(why));
}

HostGate::HostGate(std::string code, LinkLimits link_limits, GateLimits limits)
    : code_(std::move(code)), link_limits_(link_limits), limits_(limits) {}

void HostGate::acceptAll(Listener& listener, double now) {
  while (auto socket = listener.accept()) {
    auto c = std::make_unique<Connection>(std::move(socket), now, link_limits_);
    const std::string address = c->address();
    const auto from_there = std::count_if(newcomers_.begin(), newcomers_.end(),
                                          [&](const Newcomer& n) { return n.address == address; });
    if (newcomers_.size() >= limits_.most_newcomers) {
      refuseLink(*c, std::string(kBusy) + "too many connections at once, try again");
      continue;
    }
    if (static_cast<std::size_t>(from_there) >= limits_.most_per_address) {
      refuseLink(*c, std::string(kBusy) + "too many connections from your address, try again");
      continue;
    }
    newcomers_.push_back({std::move(c), address, now + limits_.hello_s});
  }
}

void HostGate::wrongGuess(const std::string& address, double now) {
  Guesses& g = guesses_[address];
  ++g.wrong;
  const int over = g.wrong - limits_.free_wrong_guesses;
  if (over > 0) {
    const double wait =
        std::min(limits_.most_penalty_s, limits_.first_penalty_s * std::ldexp(1.0, over - 1));
    g.wait_until = now + wait;
  }
}

std::optional<std::string> HostGate::refusalOf(const Hello& hello, const std::string& address,
                                               double now) {
  const auto g = guesses_.find(address);
  if (g != guesses_.end() && now < g->second.wait_until) {
    return "too many wrong join codes from your address: try again in " +
           std::to_string(static_cast<int>(std::ceil(g->second.wait_until - now))) + " s";
  }
  if (!codeMatches(hello.code, code_)) {
    wrongGuess(address, now);
    return hello.code.empty() ? "no join code: ask the host for it (--code)"
                              : "wrong join code: ask the host for it";
  }
  if (const auto mismatch = net::refusalOf(hello)) {
    build_refusal_ = *mismatch;
    return *mismatch;
  }
  if (!token_.empty() && !tokenMatches(hello.token, token_)) {
    if (!hello.token.empty()) wrongGuess(address, now);
    return "the seat is taken: only its player's seat token takes it back";
  }
  guesses_.erase(address);
  return std::nullopt;
}

std::optional<Admitted> HostGate::poll(Listener& listener, double now) {
  acceptAll(listener, now);
  for (auto it = newcomers_.begin(); it != newcomers_.end();) {
    Connection& c = *it->link;
    const auto in = c.pump(now);
    if (in.empty() && !c.closed() && now < it->deadline) {
      ++it;
      continue;
    }
    std::optional<std::string> refusal;
    std::optional<Hello> hello;
    if (c.closed()) {
      // Closed by its own doing (a broken stream is refused by the link itself).
    } else if (in.empty()) {
      refusal = "expected a hello within " + std::to_string(limits_.hello_s).substr(0, 3) + " s";
    } else {
      std::string why;
      const auto m = readMessage(in.front(), why);
      const auto* h = m ? std::get_if<Hello>(&*m) : nullptr;
      if (!h) {
        refusal = m ? "expected a hello" : "expected a hello, not " + why;
      } else if (in.size() > 1) {
        refusal = "messages before the welcome";
      } else {
        refusal = refusalOf(*h, it->address, now);
        if (!refusal) hello = *h;
      }
    }
    if (hello) {
      const bool rejoin = !token_.empty();
      if (token_.empty()) token_ = makeSeatToken();
      Admitted a{std::move(it->link), *hello, rejoin};
      newcomers_.erase(it);
      return std::optional<Admitted>(std::move(a));
    }
    if (refusal) {
      logger("net")->warn("refused {}: {}", c.remote(), cleanText(*refusal));
      refuseLink(c, *refusal);
    }
    it = newcomers_.erase(it);
  }
  return std::nullopt;
}

}  // namespace nineball::net
