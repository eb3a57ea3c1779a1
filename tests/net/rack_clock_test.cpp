// `nineball online`'s rack reads its time from the injected clock: a limit of minutes is
// reached in a moment by moving a fake clock.
#include <gtest/gtest.h>

#include <thread>

#include "common/log.hpp"
#include "net/attack_support.hpp"
#include "support/fake_clock.hpp"

namespace nineball::net {
namespace {

using namespace net_test;
using nineball::testing::FakeClock;
using Outcome = OnlineRackResult::Outcome;

// The host breaks softly from its script (nothing falls): the joiner is then to move.
const char* kSoftBreak = R"({"seed": 5, "turns": [{"heading_deg": 0, "speed": 2}]})";

class RackClock : public ::testing::Test {
 protected:
  void SetUp() override {
    setLogLevel("off");
    port_ = freePort();
    ASSERT_NE(port_, 0);
  }
  void TearDown() override { setLogLevel("warn"); }

  OnlineRackOptions hostOnTheClock() {
    OnlineRackOptions o = hostOf(port_, kSoftBreak);
    o.clock = &clock_;
    o.turn_s = 300.0;
    o.limits.silence_s = 1e9;  // the clock leaps: only the turn's limit is timed here
    return o;
  }

  // A seated raw peer that has agreed on the host's break: the host now waits for its turn.
  std::unique_ptr<RawPeer> seatedPeer() {
    auto p = std::make_unique<RawPeer>();
    EXPECT_TRUE(connectSoon(*p, port_));
    const auto seat = sitDown(*p, helloWith(kCode), true);
    EXPECT_TRUE(seat.has_value());
    if (!seat) return p;
    const json& hash = seat->after.back();
    p->send(json{{"type", "hash"}, {"index", hash["index"]}, {"hash", hash["hash"]}});
    return p;
  }

  FakeClock clock_;
  unsigned short port_ = 0;
};

TEST_F(RackClock, AFiveMinuteTurnLimitPassesWhenTheClockSaysSo) {
  RackThread host(hostOnTheClock());
  auto seated = seatedPeer();
  // The peer answers but never plays: two seconds on the clock a step.
  const double start = now();
  while (!host.finished() && now() - start < kAttackBound) {
    clock_.advance(2.0);
    seated->keepAlive();
    seated->poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const auto result = host.result(1.0);
  ASSERT_TRUE(result.has_value()) << "the host waited on for the turn";
  EXPECT_EQ(result->outcome, Outcome::LinkLost);
  EXPECT_NE(result->why.find("no turn within 300 s"), std::string::npos) << result->why;
  EXPECT_LT(now() - start, kAttackBound / 2) << "the limit was waited out, not read off the clock";
}

}  // namespace
}  // namespace nineball::net
