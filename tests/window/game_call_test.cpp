// Calling and the new decisions in the window's session: a call required, refused without
// one, passed with the shot; re-rack or play on after an illegal eight-ball break; play or
// pass after a ten-ball pot not as called.
#include <gtest/gtest.h>

#include <cmath>

#include "window/game_rolling.hpp"
#include "window/game_session.hpp"

namespace nineball::window {
namespace {

// Ten-ball from a layout (no break): the 1 in front of the top-right pocket, the cue ball
// behind it on the line to the pocket, the 10 far away.
MatchSetup tenBallLayout() {
  MatchSetup setup;
  setup.game = rules::Game::TenBall;
  const GameSession probe(setup);
  const Vec2 pocket = pocketCentre(probe, PocketId::TopRight);
  const Vec2 dir = normalized(pocket);
  const double r = probe.match().world().physics().ball_radius;
  const Vec2 one = pocket - dir * 0.25;
  setup.balls = std::vector<BallState>{
      BallState::at(kCueBall, one - dir * (0.05 + 2.0 * r)),
      BallState::at(1, one),
      BallState::at(10, {-0.5, -0.3}),
  };
  return setup;
}

TEST(GameCall, TenBallShotIsRefusedWithoutACallAndCarriesItsCall) {
  GameSession s(tenBallLayout());
  ASSERT_EQ(s.phase(), Phase::Aiming);
  ASSERT_TRUE(s.callRequired());
  EXPECT_EQ(s.callBall(), 1);
  EXPECT_FALSE(s.call().has_value());
  EXPECT_FALSE(s.shoot());
  EXPECT_NE(s.message().find("press K"), std::string::npos) << s.message();
  EXPECT_EQ(s.phase(), Phase::Aiming);
  // A click near the top-right pocket calls the 1 there.
  EXPECT_TRUE(s.clickCall(pocketCentre(s, PocketId::TopRight) * 0.99));
  ASSERT_TRUE(s.call().has_value());
  EXPECT_EQ(*s.call(), (rules::Call{1, PocketId::TopRight}));
  // A click on the 10 calls the 10 instead (the pocket stays).
  EXPECT_TRUE(s.clickCall({-0.5, -0.3}));
  EXPECT_EQ(s.callBall(), 10);
  // K: the aim guide's ball into the pocket along its path.
  s.callObvious();
  ASSERT_TRUE(s.call().has_value());
  EXPECT_EQ(*s.call(), (rules::Call{1, PocketId::TopRight}));
  s.setSpeed(2.0);
  ASSERT_TRUE(s.shoot());
  ASSERT_FALSE(s.rackTurns().empty());
  EXPECT_EQ(s.rackTurns().back().call, (rules::Call{1, PocketId::TopRight}));
  ASSERT_TRUE(roll(s));
  // The 1 went in as called: the shooter goes on.
  EXPECT_EQ(s.seatToMove(), 0) << s.message();
}

TEST(GameCall, TenBallPotNotAsCalledGivesPlayOrPass) {
  GameSession s(tenBallLayout());
  ASSERT_TRUE(s.clickCall(pocketCentre(s, PocketId::BottomLeft)));
  EXPECT_EQ(*s.call(), (rules::Call{1, PocketId::BottomLeft}));
  s.setSpeed(2.0);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  ASSERT_EQ(s.phase(), Phase::PushOutChoice) << s.message();
  EXPECT_EQ(s.match().rack().pendingDecision(), rules::Decision::PlayOrPass);
  EXPECT_NE(s.message().find("not as called"), std::string::npos) << s.message();
  EXPECT_EQ(s.seatToMove(), 1);
  s.decide(false);  // passes it back
  EXPECT_EQ(s.phase(), Phase::Aiming);
  EXPECT_EQ(s.seatToMove(), 0);
  EXPECT_NE(s.message().find("passes"), std::string::npos) << s.message();
}

TEST(GameCall, EightBallIllegalBreakGivesRerackOrPlayOn) {
  for (bool play_on : {false, true}) {
    MatchSetup setup;
    setup.game = rules::Game::EightBall;
    GameSession s(setup);
    EXPECT_FALSE(s.callRequired());  // no call on the break
    s.setSpeed(0.5);                 // too soft to be a break
    ASSERT_TRUE(s.shoot());
    ASSERT_TRUE(roll(s));
    ASSERT_EQ(s.phase(), Phase::PushOutChoice) << s.message();
    EXPECT_EQ(s.match().rack().pendingDecision(), rules::Decision::RerackOrPlayOn);
    EXPECT_NE(s.status().find("re-rack"), std::string::npos) << s.status();
    EXPECT_NE(s.message().find("Illegal break"), std::string::npos) << s.message();
    EXPECT_EQ(s.seatToMove(), 1);
    s.decide(play_on);
    EXPECT_EQ(s.phase(), Phase::Aiming);
    EXPECT_EQ(s.seatToMove(), 1);
    EXPECT_EQ(s.match().rack().isBreak(), !play_on) << s.message();
  }
}

TEST(GameCall, NineBallNeedsNoCall) {
  GameSession s{MatchSetup{}};
  EXPECT_FALSE(s.callRequired());
  EXPECT_EQ(s.callBall(), 0);
  EXPECT_FALSE(s.clickCall(pocketCentre(s, PocketId::TopLeft)));
  s.callObvious();
  EXPECT_NE(s.message().find("No call"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace nineball::window
