#include <gtest/gtest.h>

#include <cmath>

#include "nineball/shot.hpp"
#include "physics/physics_fixtures.hpp"
#include "support/paper_figures.hpp"

namespace nineball::physics_test {
namespace {

using testing::kPrintedRounding;

// The paper's example (eq. 2.1-2.5): m 0.15 kg, F 10 N for 0.2 s.
constexpr double kMass = 0.15;
constexpr double kForce = 10.0;
constexpr double kContactTime = 0.2;
constexpr double kPaperSpeed = 13.33;  // as printed, two decimals
// The printed value is rounded to the hundredth.
// v = F dt / m is one division in double: only rounding may separate it from the closed form.
constexpr double kArithmeticTolerance = 1e-12;

TEST(Impulse, PaperExampleGivesThirteenPointThreeThree) {
  const Shot shot = Shot::withImpulse(0.0, kForce, kContactTime, kMass);
  const double want = kForce * kContactTime / kMass;
  EXPECT_NEAR(shot.speed, want, kArithmeticTolerance * want);
  EXPECT_NEAR(shot.speed, kPaperSpeed, kPrintedRounding);
  EXPECT_EQ(shot.heading_rad, 0.0);
}

TEST(Impulse, HeadingSplitsTheSpeedIntoComponents) {
  // The paper measures its aim angle theta from +y (vx = v sin theta, vy = v cos theta); the
  // Shot heading is anticlockwise from +x, i.e. 90 - theta. One sin/cos pair covers all four
  // of the paper's quadrants.
  for (double theta : {20.0, 110.0, 200.0, 290.0}) {
    const Shot shot = Shot::withImpulse(90.0 - theta, kForce, kContactTime, kMass);
    const double v = kForce * kContactTime / kMass;
    const Vec2 got = shot.velocity();
    EXPECT_NEAR(got.x, v * std::sin(degToRad(theta)), kArithmeticTolerance * v) << theta;
    EXPECT_NEAR(got.y, v * std::cos(degToRad(theta)), kArithmeticTolerance * v) << theta;
  }
}

TEST(Impulse, WorldGivesTheBallTheImpulseSpeed) {
  WorstError worst("impulse: ball speed after strike + 1 step", kCollisionSpeedTolerance);
  const double v = kForce * kContactTime / kMass;
  for (double mu : {0.0, 0.01}) {
    PhysicsParams p = constantDeceleration();
    p.ball_mass = kMass;
    p.rolling_friction = mu;
    const StepParams sp;
    auto world = makeWorld(longTable(), p, sp, {makeBall(kCueBall, {-25.0, 0.0}, {}, kMass)});
    world->strike(kCueBall, Shot::withImpulse(30.0, kForce, kContactTime, kMass));
    world->step();
    const Vec2 got = stateOf(*world, kCueBall).vel;
    // The cloth takes mu g dt off the speed in the step.
    const Vec2 want = fromAngle(degToRad(30.0)) * (v - mu * p.gravity * sp.dt());
    worst.check(vectorError(got, want, v), "mu " + std::to_string(mu));
  }
}

}  // namespace
}  // namespace nineball::physics_test
