// net::Peer on a fake clock: every timeout of a game's life (nobody came, no welcome, a silent
// link, the rejoin window, the joiner's retries) is reached by moving the clock, never by
// waiting for it. The sockets are real (loopback); what they carry is awaited with a deadline.
#include "net/peer.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <thread>

#include "net/free_port.hpp"
#include "net/handshake.hpp"
#include "support/fake_clock.hpp"

namespace nineball::net {
namespace {

using nineball::testing::FakeClock;
using nineball::testing::freePort;
using What = PeerTimedOut::What;

constexpr char kCode[] = "7KQ4-ZP2M";

PeerConfig hostConfig(unsigned short port, const Clock& clock) {
  PeerConfig c;
  c.side = Side::Host;
  c.address.port = port;
  c.code = kCode;
  c.clock = &clock;
  return c;
}

PeerConfig joinerConfig(unsigned short port, const Clock& clock) {
  PeerConfig c;
  c.side = Side::Joiner;
  c.address = {"127.0.0.1", port};
  c.hello = helloFrom("Bob", kCode);
  c.clock = &clock;
  return c;
}

// Polls the peers (and runs `also`, a raw link's pump) until `done` sees an event, at most
// 10 s: loopback takes real time; the fake clock stands still meanwhile. Every event seen is
// kept in `seen`.
bool pollUntil(const std::vector<Peer*>& peers, std::vector<PeerEvent>& seen,
               const std::function<bool(const PeerEvent&)>& done,
               const std::function<void()>& also = {}) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < deadline) {
    if (also) also();
    bool hit = false;
    for (Peer* p : peers) {
      for (PeerEvent& e : p->poll()) {
        hit = hit || done(e);
        seen.push_back(std::move(e));
      }
    }
    if (hit) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

template <class T>
bool is(const PeerEvent& e) {
  return std::holds_alternative<T>(e);
}

bool timedOut(const std::vector<PeerEvent>& events, What what) {
  for (const PeerEvent& e : events) {
    if (const auto* t = std::get_if<PeerTimedOut>(&e); t && t->what == what) return true;
  }
  return false;
}

Welcome welcomeFor(const std::string& token) {
  Welcome w;
  w.protocol = kProtocolVersion;
  w.build = buildId();
  w.name = "Ann";
  w.match = {{"game", "nine-ball"}, {"seed", 3}};
  w.token = token;
  return w;
}

// A host and a joiner linked and past the handshake, on one fake clock.
struct LinkedPair {
  FakeClock clock;
  std::unique_ptr<Peer> host;
  std::unique_ptr<Peer> joiner;

  void link(PeerConfig host_config, PeerConfig joiner_config) {
    std::string why;
    host = Peer::start(host_config, why);
    ASSERT_TRUE(host) << why;
    joiner = Peer::start(joiner_config, why);
    ASSERT_TRUE(joiner) << why;
    std::vector<PeerEvent> seen;
    ASSERT_TRUE(pollUntil({host.get(), joiner.get()}, seen, is<PeerJoined>));
    EXPECT_EQ(host->stage(), Peer::Stage::Handshake);
    // Not a greeting: held back until the handshake is done, so the welcome comes first.
    host->send(HashMessage{0, 42});
    host->send(welcomeFor(host->seatToken()));
    host->handshakeDone();
    ASSERT_TRUE(pollUntil({host.get(), joiner.get()}, seen, is<PeerMessage>));
    const auto& first = std::get<PeerMessage>(seen.back()).message;
    ASSERT_TRUE(std::holds_alternative<Welcome>(first));
    joiner->handshakeDone();
    EXPECT_EQ(host->stage(), Peer::Stage::Playing);
    EXPECT_EQ(joiner->stage(), Peer::Stage::Playing);
  }
};

TEST(Peer, AHostThatNobodyJoinsTimesOutOnTheClockAlone) {
  FakeClock clock;
  PeerConfig config = hostConfig(freePort(), clock);
  config.wait_s = 30.0;
  std::string why;
  auto host = Peer::start(config, why);
  ASSERT_TRUE(host) << why;
  EXPECT_TRUE(host->poll().empty());
  clock.advance(29.9);
  EXPECT_TRUE(host->poll().empty());
  EXPECT_EQ(host->stage(), Peer::Stage::Waiting);
  clock.advance(0.2);
  EXPECT_TRUE(timedOut(host->poll(), What::NobodyCame));
  EXPECT_EQ(host->stage(), Peer::Stage::Over);
}

TEST(Peer, AHostWithoutAWaitingLimitWaitsForEver) {
  FakeClock clock;
  std::string why;
  auto host = Peer::start(hostConfig(freePort(), clock), why);
  ASSERT_TRUE(host) << why;
  clock.advance(1e6);
  EXPECT_TRUE(host->poll().empty());
  EXPECT_EQ(host->stage(), Peer::Stage::Waiting);
}

TEST(Peer, ATakenPortIsSaidAtStart) {
  FakeClock clock;
  const unsigned short port = freePort();
  std::string why;
  auto first = Peer::start(hostConfig(port, clock), why);
  ASSERT_TRUE(first) << why;
  EXPECT_FALSE(Peer::start(hostConfig(port, clock), why));
  EXPECT_NE(why.find("cannot listen"), std::string::npos) << why;
}

TEST(Peer, AHostMakesAJoinCodeWhenGivenNone) {
  FakeClock clock;
  PeerConfig config = hostConfig(freePort(), clock);
  config.code.clear();
  std::string why;
  auto host = Peer::start(config, why);
  ASSERT_TRUE(host) << why;
  EXPECT_EQ(host->code().size(), 9u) << host->code();
}

TEST(Peer, AJoinerWelcomedPlaysAndTheHandshakeHoldsBackTheRack) {
  LinkedPair pair;
  const unsigned short port = freePort();
  pair.link(hostConfig(port, pair.clock), joinerConfig(port, pair.clock));
  // The hash sent during the handshake never went out; one sent now does.
  pair.host->send(HashMessage{1, 7});
  std::vector<PeerEvent> seen;
  ASSERT_TRUE(pollUntil({pair.host.get(), pair.joiner.get()}, seen, is<PeerMessage>));
  const auto* hash = std::get_if<HashMessage>(&std::get<PeerMessage>(seen.back()).message);
  ASSERT_TRUE(hash);
  EXPECT_EQ(hash->index, 1u);
}

TEST(Peer, ASilentLinkIsLostAndTheRejoinWindowRunsOnTheClock) {
  LinkedPair pair;
  const unsigned short port = freePort();
  PeerConfig host = hostConfig(port, pair.clock);
  host.rejoin_s = 60.0;
  pair.link(host, joinerConfig(port, pair.clock));
  // The joiner stops answering: only the clock moves, past the link's silence limit.
  pair.clock.advance(LinkLimits{}.silence_s + 0.5);
  std::vector<PeerEvent> events = pair.host->poll();
  ASSERT_EQ(events.size(), 1u);
  ASSERT_TRUE(is<PeerLost>(events[0]));
  EXPECT_NE(std::get<PeerLost>(events[0]).reason.find("stopped answering"), std::string::npos);
  EXPECT_EQ(pair.host->stage(), Peer::Stage::Lost);
  EXPECT_DOUBLE_EQ(pair.host->rejoinLeft(), 60.0);
  pair.clock.advance(59.9);
  EXPECT_TRUE(pair.host->poll().empty());
  EXPECT_EQ(pair.host->stage(), Peer::Stage::Lost);
  pair.clock.advance(0.2);
  EXPECT_TRUE(timedOut(pair.host->poll(), What::NoRejoin));
  EXPECT_EQ(pair.host->stage(), Peer::Stage::Over);
}

TEST(Peer, ARejoinWithTheSeatTokenWithinTheWindowGoesOn) {
  LinkedPair pair;
  const unsigned short port = freePort();
  PeerConfig host = hostConfig(port, pair.clock);
  host.limits.silence_s = 100.0;  // the rejoin's window alone is timed here
  pair.link(host, joinerConfig(port, pair.clock));
  const std::string token = pair.host->seatToken();
  ASSERT_FALSE(token.empty());
  pair.joiner.reset();  // the joiner's program is gone: its link closes
  std::vector<PeerEvent> seen;
  ASSERT_TRUE(pollUntil({pair.host.get()}, seen, is<PeerLost>));
  EXPECT_EQ(pair.host->stage(), Peer::Stage::Lost);
  pair.clock.advance(30.0);
  PeerConfig back = joinerConfig(port, pair.clock);
  back.hello = helloFrom("Bob", kCode, token);
  std::string why;
  auto joiner = Peer::start(back, why);
  ASSERT_TRUE(joiner) << why;
  ASSERT_TRUE(pollUntil({pair.host.get(), joiner.get()}, seen, is<PeerJoined>));
  // Still the rejoin's stage until the rack's driver has welcomed it.
  EXPECT_EQ(pair.host->stage(), Peer::Stage::Lost);
  pair.host->handshakeDone();
  pair.clock.advance(35.0);  // past the first window's end: it is closed
  EXPECT_EQ(pair.host->stage(), Peer::Stage::Playing);
  EXPECT_FALSE(timedOut(pair.host->poll(), What::NoRejoin));
}

TEST(Peer, AJoinerGivesUpOnAHostThatNeverWelcomes) {
  FakeClock clock;
  const unsigned short port = freePort();
  std::string why;
  auto silent_host = Listener::open(port, why);
  ASSERT_TRUE(silent_host) << why;
  PeerConfig config = joinerConfig(port, clock);
  config.welcome_s = 10.0;
  config.limits.silence_s = 60.0;  // the welcome's limit comes first
  auto joiner = Peer::start(config, why);
  ASSERT_TRUE(joiner) << why;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  std::unique_ptr<sf::TcpSocket> accepted;
  while (!(accepted && joiner->handshaking()) && std::chrono::steady_clock::now() < deadline) {
    EXPECT_TRUE(joiner->poll().empty());
    if (!accepted) accepted = silent_host->accept();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_TRUE(joiner->handshaking());
  EXPECT_EQ(joiner->stage(), Peer::Stage::Handshake);
  clock.advance(9.9);
  EXPECT_TRUE(joiner->poll().empty());
  clock.advance(0.2);
  EXPECT_TRUE(timedOut(joiner->poll(), What::NoWelcome));
  EXPECT_FALSE(joiner->linked());
  EXPECT_EQ(joiner->stage(), Peer::Stage::Waiting);  // to try again, unless the driver ends
}

TEST(Peer, AJoinerAwaitsTheWelcomeNoLongerThanItsWaitWhenAsked) {
  FakeClock clock;
  const unsigned short port = freePort();
  std::string why;
  auto silent_host = Listener::open(port, why);
  ASSERT_TRUE(silent_host) << why;
  PeerConfig config = joinerConfig(port, clock);
  config.wait_s = 2.0;
  config.welcome_s = 5.0;
  config.welcome_within_wait = true;
  auto joiner = Peer::start(config, why);
  ASSERT_TRUE(joiner) << why;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!joiner->handshaking() && std::chrono::steady_clock::now() < deadline) {
    EXPECT_TRUE(joiner->poll().empty());
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_TRUE(joiner->handshaking());
  clock.advance(1.9);
  EXPECT_TRUE(joiner->poll().empty());
  clock.advance(0.2);  // 2.1 s: past the wait, well short of welcome_s
  EXPECT_TRUE(timedOut(joiner->poll(), What::NoWelcome));
}

TEST(Peer, AJoinerRetriesOnTheClockAndGivesUpAfterItsWait) {
  FakeClock clock;
  PeerConfig config = joinerConfig(freePort(), clock);  // nobody listens there
  config.retry_s = 1.0;
  config.wait_s = 5.0;
  std::string why;
  auto joiner = Peer::start(config, why);
  ASSERT_TRUE(joiner) << why;
  std::vector<PeerEvent> seen;
  ASSERT_TRUE(pollUntil({joiner.get()}, seen, is<PeerUnreachable>));
  EXPECT_FALSE(joiner->lastProblem().empty());
  // No second attempt until the clock says so.
  for (int i = 0; i < 50; ++i) EXPECT_TRUE(joiner->poll().empty());
  clock.advance(1.0);
  ASSERT_TRUE(pollUntil({joiner.get()}, seen, is<PeerUnreachable>));
  EXPECT_EQ(joiner->stage(), Peer::Stage::Waiting);
  clock.advance(4.5);
  EXPECT_TRUE(timedOut(joiner->poll(), What::NobodyCame));
}

TEST(Peer, AHostOverRefusesLateComersWithWhy) {
  FakeClock clock;
  const unsigned short port = freePort();
  std::string why;
  auto host = Peer::start(hostConfig(port, clock), why);
  ASSERT_TRUE(host) << why;
  host->end("Bob left");
  auto socket = connectTo({"127.0.0.1", port}, 5.0, why);
  ASSERT_TRUE(socket) << why;
  Connection late(std::move(socket), clock.now());
  std::vector<nlohmann::json> got;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (got.empty() && std::chrono::steady_clock::now() < deadline) {
    EXPECT_TRUE(host->poll().empty());
    got = late.pump(clock.now());
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].value("type", ""), "refuse");
  EXPECT_NE(got[0].value("reason", "").find("the game is over: Bob left"), std::string::npos);
}

TEST(Peer, ABadMessageIsReportedAndTheDriverRefusesIt) {
  FakeClock clock;
  const unsigned short port = freePort();
  std::string why;
  auto host = Peer::start(hostConfig(port, clock), why);
  ASSERT_TRUE(host) << why;
  auto socket = connectTo({"127.0.0.1", port}, 5.0, why);
  ASSERT_TRUE(socket) << why;
  Connection raw(std::move(socket), clock.now());
  raw.send(toJson(helloFrom("Mallory", kCode)));
  std::vector<PeerEvent> seen;
  const auto pumpRaw = [&] { raw.pump(clock.now()); };
  ASSERT_TRUE(pollUntil({host.get()}, seen, is<PeerJoined>, pumpRaw));
  raw.send({{"type", "turn"}});  // a turn without its fields
  ASSERT_TRUE(pollUntil({host.get()}, seen, is<PeerBadMessage>, pumpRaw));
  EXPECT_FALSE(std::get<PeerBadMessage>(seen.back()).why.empty());
  // The driver says why and lets it go; a refused peer may come back (the rejoin window).
  ASSERT_TRUE(host->linked());
  host->send(Refuse{"disconnected: you sent a bad message"});
  host->flush();
  host->lose("it sent a bad message");
  EXPECT_FALSE(host->linked());
  EXPECT_EQ(host->stage(), Peer::Stage::Waiting);  // the rack had not begun
  std::vector<nlohmann::json> got;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (got.empty() && std::chrono::steady_clock::now() < deadline) {
    got = raw.pump(clock.now());
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_FALSE(got.empty());
  EXPECT_EQ(got[0].value("type", ""), "refuse");
}

}  // namespace
}  // namespace nineball::net
