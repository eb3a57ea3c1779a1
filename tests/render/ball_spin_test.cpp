// Each ball's orientation, turned frame by frame by its spin, against the physics: a rolling ball
// turns by the distance over its radius, a stun ball slides without turning, a draw shot turns
// backwards, side spin turns the number in place; and the colour of each point of it.
#include "render/ball_spin.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "nineball/engine.hpp"
#include "nineball/params.hpp"

namespace nineball::render {
namespace {

constexpr double kFrame = 1.0 / 60.0;

// One ball alone on the table, started with velocity v and spin w, stepped at 60 Hz; the
// orientation turned by every frame's state.
struct OneBall {
  std::unique_ptr<Engine> engine;
  BallSpins spins;
  double travelled = 0.0;

  OneBall(Vec2 v, Vec3 w) {
    StepParams step;
    step.engine = EngineKind::named("reference");
    engine = makeEngine(TableDef{}, PhysicsParams::real(), step);
    BallState b = BallState::at(1, {-0.8, 0.0}, v);
    b.w = w;
    engine->addBall(b);
    spins.advance(engine->balls(), engine->time());
  }
  void frames(int n) {
    for (int i = 0; i < n; ++i) {
      const Vec2 before = engine->balls()[0].pos;
      engine->step();
      travelled += length(engine->balls()[0].pos - before);
      spins.advance(engine->balls(), engine->time());
    }
  }
  Vec3 number() const { return spins.of(1).toTable({0.0, 0.0, 1.0}); }
};

TEST(BallSpins, ARollingBallTurnsByTheDistanceOverItsRadius) {
  const double r = PhysicsParams::real().ball_radius;
  OneBall run({1.2, 0.0}, {0.0, 1.2 / r, 0.0});  // rolling along +x
  run.frames(20);
  const Vec3 n = run.number();
  // The number, on top at the start, has rolled forward over the top by travelled / R.
  const double turned = std::atan2(n.x, n.z);
  EXPECT_NEAR(turned, std::fmod(run.travelled / r + kPi, 2.0 * kPi) - kPi, 1e-6);
  EXPECT_NEAR(n.y, 0.0, 1e-12);
}

TEST(BallSpins, AStunBallSlidesWithoutTurning) {
  const double r = PhysicsParams::real().ball_radius;
  OneBall run({3.0, 0.0}, {0.0, 0.0, 0.0});
  run.frames(1);
  // Friction starts the roll at once, but over a frame it has turned the ball by a sliver of
  // what rolling would (friction's w grows as t, the turn as t^2).
  const Vec3 n = run.number();
  const double turned = std::atan2(n.x, n.z);
  EXPECT_LT(std::abs(turned), 0.05 * run.travelled / r);
  EXPECT_GT(turned, 0.0);  // and what little there is, forward
}

TEST(BallSpins, ADrawShotTurnsBackwardsWhileItSlidesForward) {
  const double r = PhysicsParams::real().ball_radius;
  OneBall run({2.0, 0.0}, {0.0, -2.0 / r, 0.0});  // backspin: the top moves back
  run.frames(2);
  EXPECT_GT(run.engine->balls()[0].pos.x, -0.8 + 0.05);
  EXPECT_LT(run.number().x, -0.1);
}

TEST(BallSpins, SideSpinTurnsTheNumberInPlace) {
  OneBall run({0.0, 0.0}, {0.0, 0.0, 20.0});
  run.frames(3);
  const Vec3 up = run.number();
  EXPECT_NEAR(up.z, 1.0, 1e-12);
  // The body's x axis has turned about the vertical by the spin's own angle.
  const Vec3 side = run.spins.of(1).toTable({1.0, 0.0, 0.0});
  EXPECT_GT(std::atan2(side.y, side.x), 0.5);
  EXPECT_NEAR(run.engine->balls()[0].pos.x, -0.8, 1e-12);
}

TEST(BallSpins, TheTurnIsTheSameAtAnyFrameRate) {
  // Spin changing at a steady rate about a fixed axis, as the cloth changes it within a phase.
  auto turn = [](int frames) {
    BallSpins spins;
    for (int k = 0; k <= frames; ++k) {
      const double t = static_cast<double>(k) / frames;
      BallState b = BallState::at(3, {});
      b.w = {0.0, 40.0 - 30.0 * t, 0.0};
      spins.advance({b}, t);
    }
    return spins.of(3).toTable({0.0, 0.0, 1.0});
  };
  const Vec3 a = turn(30), b = turn(144);
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.z, b.z, 1e-12);
  // 40 - 15 = 25 rad over the second.
  EXPECT_NEAR(std::atan2(a.x, a.z), std::remainder(25.0, 2.0 * kPi), 1e-9);
}

TEST(BallSpins, AJumpInTheClockTurnsNothingAndADropIsSeen) {
  BallSpins spins;
  BallState b = BallState::at(5, {0.1, 0.2});
  b.w = {0.0, 50.0, 0.0};
  spins.advance({b}, 10.0);
  spins.advance({b}, 2.0);  // a replay starting over
  EXPECT_NEAR(spins.of(5).toTable({0.0, 0.0, 1.0}).z, 1.0, 1e-12);
  spins.advance({b}, 2.01);
  b.pocket = PocketId::TopLeft;
  spins.advance({b}, 2.02);
  ASSERT_NE(spins.dropOf(5), nullptr);
  EXPECT_DOUBLE_EQ(spins.dropOf(5)->time, 2.02);
}

TEST(LitBall, TheNumberDiscFacesUpAndRollsOverTheSide) {
  const BallLook solid = poolBallLook(2);
  const Orientation up;
  // Number up: the centre is the white disc, the side the ball's colour.
  const Shade centre = litBall(solid, 2, up, 0.0, 0.0, 20.0, nullptr, nullptr);
  const Shade side = litBall(solid, 2, up, 0.8, 0.0, 20.0, nullptr, nullptr);
  EXPECT_GT(centre.b, 0.8);
  EXPECT_GT(centre.r, 0.8);
  EXPECT_LT(side.r, 0.3);
  // A quarter turn forward (+x): the disc is at the +x rim, the top is the ball's colour.
  const Orientation rolled = up.turned({0.0, 0.5 * kPi, 0.0});
  EXPECT_LT(litBall(solid, 2, rolled, 0.0, 0.0, 20.0, nullptr, nullptr).r, 0.3);
  // (the rim away from the light: white dimmed, against the blue's red of nearly nothing)
  EXPECT_GT(litBall(solid, 2, rolled, 0.95, 0.0, 20.0, nullptr, nullptr).r, 0.3);
  EXPECT_LT(litBall(solid, 2, up, 0.95, 0.0, 20.0, nullptr, nullptr).r, 0.1);
  // Outside the disc nothing is drawn; the lit colour is brighter towards the light.
  EXPECT_EQ(litBall(solid, 2, up, 0.8, 0.7, 20.0, nullptr, nullptr).a, 0.0);
  EXPECT_GT(litColour({200, 200, 200}, -0.3, 0.4).r, litColour({200, 200, 200}, 0.3, -0.4).r);
}

TEST(LitBall, AStripeIsABandRoundTheBallAndTheCueBallHasSpots) {
  const BallLook stripe = poolBallLook(11);
  const Orientation up;
  EXPECT_GT(litBall(stripe, 11, up, 0.0, 0.8, 20.0, nullptr, nullptr).b, 0.5);  // white cap
  EXPECT_LT(litBall(stripe, 11, up, 0.8, 0.0, 20.0, nullptr, nullptr).b, 0.3);  // red band
  const Shade spot =
      litBall(poolBallLook(kCueBall), kCueBall, up, 0.0, 0.0, 20.0, nullptr, nullptr);
  EXPECT_GT(spot.r, 2.0 * spot.g);
}

TEST(GlyphScale, TwoDigitsFitTheNumberDiscAndOneDigitKeepsItsHeight) {
  // A digit is about 0.6 of its height wide in the bold face: "12" 1.2, "8" 0.6.
  const double cell = 64.0, height = 46.0;
  for (double digits : {1.0, 2.0}) {
    const double width = 0.6 * height * digits;
    const double s = glyphScale(width, height, cell);
    EXPECT_LE(s * width, 0.78 * cell + 1e-9) << digits;
    EXPECT_LE(s * height, 0.62 * cell + 1e-9) << digits;
  }
  EXPECT_DOUBLE_EQ(glyphScale(0.6 * height, height, cell) * height, 0.62 * cell);
}

}  // namespace
}  // namespace nineball::render
