// The other player's cue as the window shows it: eased towards each aim heard, the short way
// round; and the aim sent at most 8 times a second.
#include "window/remote_aim.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "window/online_play.hpp"

namespace nineball::window {
namespace {

constexpr double kPi = 3.14159265358979323846;

AimPose aim(double heading, double speed = 3.0) {
  AimPose p;
  p.heading_rad = heading;
  p.speed = speed;
  return p;
}

TEST(AimSmoother, ShowsNothingBeforeTheFirstAimAndTheFirstAtOnce) {
  AimSmoother s;
  EXPECT_FALSE(s.advance(0.016).has_value());
  s.heard(aim(1.0, 4.0));
  const auto shown = s.advance(0.016);
  ASSERT_TRUE(shown.has_value());
  EXPECT_DOUBLE_EQ(shown->heading_rad, 1.0);
  EXPECT_DOUBLE_EQ(shown->speed, 4.0);
}

TEST(AimSmoother, EasesTowardsANewAimWithoutJumpingAndArrives) {
  AimSmoother s;
  s.heard(aim(0.0, 2.0));
  s.advance(0.016);
  s.heard(aim(0.5, 6.0));
  const auto first = s.advance(1.0 / 60.0);
  ASSERT_TRUE(first.has_value());
  // One frame covers 1 - exp(-1/60 / 0.08) = 19 % of the way, not all of it.
  EXPECT_GT(first->heading_rad, 0.05);
  EXPECT_LT(first->heading_rad, 0.15);
  EXPECT_GT(first->speed, 2.0);
  EXPECT_LT(first->speed, 3.5);
  std::optional<AimPose> later;
  for (int i = 0; i < 60; ++i) later = s.advance(1.0 / 60.0);
  EXPECT_NEAR(later->heading_rad, 0.5, 1e-4);
  EXPECT_NEAR(later->speed, 6.0, 1e-3);
}

TEST(AimSmoother, TurnsTheShortWayRoundThroughPi) {
  // From just under +pi to just over -pi is 0.2 rad through pi, not 6.08 rad back round.
  EXPECT_NEAR(std::abs(easeAngle(kPi - 0.1, -kPi + 0.1, 0.5)), kPi, 1e-9);
  EXPECT_NEAR(easeAngle(0.1, -0.1, 0.5), 0.0, 1e-12);
}

TEST(AimSmoother, CarriesTheCueBallInHandAndDropsItWhenNoLongerHeld) {
  AimSmoother s;
  AimPose p = aim(0.0);
  p.cue = Vec2{-0.5, 0.0};
  s.heard(p);
  s.advance(0.016);
  p.cue = Vec2{-0.3, 0.1};
  s.heard(p);
  const auto moving = s.advance(0.016);
  ASSERT_TRUE(moving->cue.has_value());
  EXPECT_GT(moving->cue->x, -0.5);
  EXPECT_LT(moving->cue->x, -0.3);
  p.cue.reset();
  s.heard(p);
  EXPECT_FALSE(s.advance(0.016)->cue.has_value());
  s.reset();
  EXPECT_FALSE(s.advance(0.016).has_value());
}

TEST(AimThrottle, SendsAtMostEightASecondAndOnlyWhatChanged) {
  AimThrottle t;
  EXPECT_TRUE(t.due(aim(0.0), 10.0));
  EXPECT_FALSE(t.due(aim(0.1), 10.05));  // too soon
  EXPECT_TRUE(t.due(aim(0.1), 10.13));
  EXPECT_FALSE(t.due(aim(0.1), 11.0));  // unchanged
  int sent = 0;
  for (int frame = 0; frame < 60; ++frame) {
    if (t.due(aim(0.2 + 0.01 * frame), 20.0 + frame / 60.0)) ++sent;
  }
  EXPECT_LE(sent, 8);
  EXPECT_GE(sent, 7);
}

TEST(ClockText, ShowsMinutesAndSecondsRoundedUp) {
  EXPECT_EQ(clockText(60.0), "1:00");
  EXPECT_EQ(clockText(44.2), "0:45");
  EXPECT_EQ(clockText(-3.0), "0:00");
}

}  // namespace
}  // namespace nineball::window
