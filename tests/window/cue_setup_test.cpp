// The cue being set: each setting held within its range, the gauge linear in speed, the tip
// pulled in to just inside its limit, a played shot's settings taken as given, and a new turn
// centring the tip, levelling the cue and forgetting the cue ball's spot.
#include "window/cue_setup.hpp"

#include <gtest/gtest.h>

namespace nineball::window {
namespace {

TEST(CueSetup, SpeedAndTiltStayInRangeAndTheGaugeIsLinearInSpeed) {
  CueSetup cue(3.0);
  EXPECT_DOUBLE_EQ(cue.speed(), 3.0);
  cue.setSpeed(100.0);
  EXPECT_DOUBLE_EQ(cue.speed(), CueSetup::kMaxSpeed);
  EXPECT_DOUBLE_EQ(cue.power(), 1.0);
  cue.setSpeed(-1.0);
  EXPECT_DOUBLE_EQ(cue.speed(), CueSetup::kMinSpeed);
  EXPECT_DOUBLE_EQ(cue.power(), 0.0);
  cue.setPower(0.5);
  EXPECT_DOUBLE_EQ(cue.speed(), 0.5 * (CueSetup::kMinSpeed + CueSetup::kMaxSpeed));
  cue.setElevation(degToRad(90.0));
  EXPECT_DOUBLE_EQ(cue.elevation(), degToRad(CueSetup::kMaxElevationDeg));
  cue.setElevation(-0.1);
  EXPECT_DOUBLE_EQ(cue.elevation(), 0.0);
}

TEST(CueSetup, TheTipIsPulledInJustInsideItsLimitAlongItsOwnDirection) {
  CueSetup cue(3.0);
  cue.setTip({0.3, 0.4}, 0.6);  // inside: kept
  EXPECT_EQ(cue.tip(), (Vec2{0.3, 0.4}));
  cue.setTip({0.6, 0.8}, 0.5);  // twice the limit: halved, and a hair inside
  EXPECT_LT(length(cue.tip()), 0.5);
  EXPECT_NEAR(length(cue.tip()), 0.5, 1e-9);
  EXPECT_NEAR(cue.tip().x / cue.tip().y, 0.75, 1e-12);
}

TEST(CueSetup, APlayedShotIsTakenAsGivenAndANewTurnStartsCentredAndLevel) {
  CueSetup cue(3.0);
  cue.setSpot(Vec2{0.1, 0.2});
  cue.take(1.25, 50.0, {0.9, 0.0}, 0.3);  // the computer's settings: only the speed is held
  EXPECT_DOUBLE_EQ(cue.heading(), 1.25);
  EXPECT_DOUBLE_EQ(cue.speed(), CueSetup::kMaxSpeed);
  EXPECT_EQ(cue.tip(), (Vec2{0.9, 0.0}));
  EXPECT_DOUBLE_EQ(cue.elevation(), 0.3);
  cue.newTurn();
  EXPECT_EQ(cue.tip(), Vec2{});
  EXPECT_DOUBLE_EQ(cue.elevation(), 0.0);
  EXPECT_FALSE(cue.spot());
  EXPECT_DOUBLE_EQ(cue.heading(), 1.25);  // the aim is the next turn's to set
}

}  // namespace
}  // namespace nineball::window
