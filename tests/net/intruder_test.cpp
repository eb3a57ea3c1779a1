// A host with a player seated goes on talking to that player while it reads someone else who
// connects (a rejoin, or anyone: a port scanner that connects and says nothing). Were it to fall
// silent on the seated player for the newcomer's handshake (up to the silence limit, at most
// 5 s), a player whose silence limit is no longer than that would drop a healthy link.
#include <gtest/gtest.h>

#include <iostream>
#include <memory>
#include <vector>

#include "common/log.hpp"
#include "net/handshake.hpp"
#include "net/hostile_messages.hpp"
#include "net/live_host.hpp"
#include "net/raw_peer.hpp"

namespace nineball::net {
namespace {

using namespace net_test;

#ifdef NINEBALL_SANITIZED
constexpr double kBound = 20.0;
constexpr double kSlack = 0.3;  // s
#else
constexpr double kBound = 5.0;
constexpr double kSlack = 0.15;
#endif

class Intruders : public ::testing::Test {
 protected:
  void SetUp() override { setLogLevel("off"); }
  void TearDown() override { setLogLevel("warn"); }
};

TEST_F(Intruders, SilentIntrudersDoNotSilenceTheHostTowardsTheSeatedPlayer) {
  const unsigned short port = freePort();
  ASSERT_NE(port, 0);
  const std::string text = R"({"seed": 5, "players": {"A": "ai:beginner"}})";
  OnlineRackOptions host;
  host.side = Side::Host;
  host.address = {"127.0.0.1", port};
  host.script = scriptOf(text);
  host.match = matchPart(json::parse(text));
  host.wait_s = 4 * kBound;
  host.rejoin_s = 4 * kBound;
  host.limits.silence_s = 0.5;  // an intruder that says nothing is dropped after this
  host.limits.ping_s = 0.1;
  host.code = kCode;
  RackThread rack(host);

  RawPeer seated;
  const double deadline = now() + kBound;
  while (!seated.connect(port, 1.0) && now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(seated.send(goodHello("Seated")));
  // The welcome, the host's break and its hash.
  int hashes = 0;
  std::string token;
  for (double until = now() + 4 * kBound; hashes == 0 && now() < until;) {
    const json m = seated.next(until - now());
    ASSERT_FALSE(m.is_null()) << "no welcome and break";
    hashes += m.value("type", "") == "hash";
    if (m.value("type", "") == "welcome") token = m.value("token", "");
  }

  // Three intruders connect at once and say nothing; the host reads them one by one.
  seated.resetQuiet();
  std::vector<std::unique_ptr<RawPeer>> intruders;
  for (int i = 0; i < 3; ++i) {
    intruders.push_back(std::make_unique<RawPeer>());
    ASSERT_TRUE(intruders.back()->connect(port, kBound));
  }
  // The seated player pings on meanwhile, as a player's nineball does.
  const double until = now() + kBound;
  std::size_t dropped = 0;
  while (dropped < intruders.size() && now() < until) {
    dropped = 0;
    for (auto& intruder : intruders) {
      intruder->poll();
      dropped += intruder->closed();
    }
    seated.keepAlive();
    seated.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_EQ(dropped, intruders.size()) << "silent intruders were never dropped";
  const double quiet = seated.longestQuiet();
  std::cout << "[intruders] the host was quiet towards the seated player for at most " << quiet
            << " s (its ping interval " << host.limits.ping_s << " s, silence limit "
            << host.limits.silence_s << " s)\n";
  // Pings keep coming at their interval (with some slack for a busy machine), not a silence
  // limit apart.
  EXPECT_LT(quiet, host.limits.ping_s + kSlack)
      << "the host fell silent on the seated player while it read the intruders";
  EXPECT_FALSE(seated.closed());

  // Still seated, still in the game: its own broken turn is refused by name.
  seated.send(brokenTurnMessage(*std::make_unique<Rng>(1), 1));
  const Answer own = seated.awaitRefusal(kBound, true);
  EXPECT_EQ(own.kind, Answer::Kind::Refused);
  EXPECT_NE(own.reason.find("disconnected: you sent"), std::string::npos) << own.reason;

  // Ends the host: a seated player who leaves.
  RawPeer last;
  ASSERT_TRUE(last.connect(port, kBound));
  last.send(goodHello("Last", token));
  last.next(kBound);
  last.send(json{{"type", "bye"}, {"reason", "the test is over"}, {"finished", false}});
  const auto result = rack.result(kBound);
  ASSERT_TRUE(result.has_value()) << "the host did not end";
  EXPECT_EQ(result->outcome, OnlineRackResult::Outcome::LinkLost) << result->why;
}

}  // namespace
}  // namespace nineball::net
