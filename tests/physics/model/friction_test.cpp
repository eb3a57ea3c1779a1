#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "physics/physics_fixtures.hpp"

namespace nineball::physics_test {
namespace {

constexpr double kStartX = -29.0;  // near the left end of the 60 m table

struct Stop {
  double distance = 0.0;
  double time = 0.0;  // the AllAtRest event
};

StepParams fineStep() {
  StepParams s;
  s.hz = 1000.0;
  return s;
}

Stop rollToRest(const PhysicsParams& p, const StepParams& sp, double v0) {
  auto world = makeWorld(longTable(), p, sp, {makeBall(kCueBall, {kStartX, 0.0})});
  world->strike(kCueBall, Shot::withSpeed(0.0, v0));
  world->runUntilRest();
  EXPECT_TRUE(world->atRest());
  EXPECT_EQ(countEvents(world->events(), EventType::Cushion), 0) << "ran into a cushion";
  const auto rest = firstEvent(world->events(), EventType::AllAtRest);
  EXPECT_TRUE(rest.has_value());
  const BallState b = stateOf(*world, kCueBall);
  EXPECT_EQ(b.pos.y, 0.0);
  return {b.pos.x - kStartX, rest ? rest->t : 0.0};
}

TEST(Friction, StoppingDistanceAndTimeMatchTheClosedForm) {
  WorstError distance("friction: stopping distance v0^2/(2 mu g)", kStoppingTolerance);
  WorstError time("friction: stopping time v0/(mu g)", kStoppingTolerance);
  struct Case {
    double mu, v0;
  };
  // mu 0.2 fits every speed on the 60 m table; the real 0.01 fits the two slow ones.
  for (const Case c : {Case{0.2, 0.5}, Case{0.2, 2.0}, Case{0.2, 5.0}, Case{0.2, 10.0},
                       Case{0.01, 0.5}, Case{0.01, 2.0}}) {
    PhysicsParams p = constantDeceleration();
    p.rolling_friction = c.mu;
    const double a = c.mu * p.gravity;
    const Stop s = rollToRest(p, StepParams{}, c.v0);
    const std::string where = "mu " + std::to_string(c.mu) + " v0 " + std::to_string(c.v0);
    distance.check(relativeError(s.distance, c.v0 * c.v0 / (2.0 * a), 1.0), where);
    time.check(relativeError(s.time, c.v0 / a, 1.0), where);
  }
}

TEST(Friction, StoppingDistanceDoesNotDependOnTheStepRate) {
  // The paper's program took mu g off once per frame, so its balls ran further at a higher
  // frame rate. Here 60 Hz (which also makes the world sub-step fast balls), 120 Hz and the
  // default must all give the closed form.
  WorstError distance("friction: stopping distance at 60/120/500/2000 Hz", kStoppingTolerance);
  PhysicsParams p = constantDeceleration();
  p.rolling_friction = 0.2;
  const double a = p.rolling_friction * p.gravity;
  for (double hz : {60.0, 120.0, 500.0, 2000.0}) {
    StepParams sp;
    sp.hz = hz;
    for (double v0 : {0.5, 5.0, 10.0}) {
      const Stop s = rollToRest(p, sp, v0);
      distance.check(relativeError(s.distance, v0 * v0 / (2.0 * a), 1.0),
                     "hz " + std::to_string(hz) + " v0 " + std::to_string(v0));
    }
  }
}

TEST(Friction, SpeedFallsLinearly) {
  // v(t) = v0 - mu g t at every step, not only at the end.
  WorstError speed("friction: speed v0 - mu g t at t = 0.25 T .. 0.75 T", kStoppingTolerance);
  PhysicsParams p = constantDeceleration();
  p.rolling_friction = 0.2;
  const double a = p.rolling_friction * p.gravity;
  const double v0 = 5.0;
  auto world = makeWorld(longTable(), p, StepParams{}, {makeBall(kCueBall, {kStartX, 0.0})});
  world->strike(kCueBall, Shot::withSpeed(0.0, v0));
  const double stop = v0 / a;
  for (double frac : {0.25, 0.5, 0.75}) {
    world->runFor(frac * stop - world->time());
    const double t = world->time();
    speed.check(relativeError(length(stateOf(*world, kCueBall).vel), v0 - a * t, v0),
                "t " + std::to_string(t));
  }
}

TEST(Friction, DampingModelFollowsItsExponentialLaw) {
  // Box2D's damping is v <- v / (1 + h c) per step, whose limit is v0 exp(-c t); the ball then
  // has travelled (v0 - v) / c. That law, not mu g, is what this model must follow.
  WorstError speed("damping: speed v0 exp(-c t)", kStoppingTolerance);
  WorstError distance("damping: distance (v0 - v)/c", kStoppingTolerance);
  for (double c : {0.2, 1.0}) {
    PhysicsParams p = constantDeceleration();
    p.cloth = ClothModel::Damping;
    p.linear_damping = c;
    for (double v0 : {0.5, 2.0, 5.0, 10.0}) {
      // Box2D damps by 1/(1 + h c) per step: its law tends to exp(-c t) as the step shrinks
      // (off by c^2 h t / 2), so the comparison runs at a fine fixed step.
      auto world = makeWorld(longTable(), p, fineStep(), {makeBall(kCueBall, {kStartX, 0.0})});
      world->strike(kCueBall, Shot::withSpeed(0.0, v0));
      const double t = 2.0;
      world->runFor(t);
      ASSERT_NEAR(world->time(), t, 1e-12);
      const BallState b = stateOf(*world, kCueBall);
      const double v = length(b.vel);
      const std::string where = "c " + std::to_string(c) + " v0 " + std::to_string(v0);
      speed.check(relativeError(v, v0 * std::exp(-c * t), 1.0), where);
      distance.check(relativeError(b.pos.x - kStartX, (v0 - v) / c, 1.0), where);
    }
  }
}

TEST(Friction, DampingModelIsNotTheConstantDecelerationLaw) {
  // The two cloth models differ in kind: with c chosen so that both start with the same
  // deceleration (c v0 = mu g), the damped ball has not stopped when the friction ball has.
  PhysicsParams p = constantDeceleration();
  p.cloth = ClothModel::Damping;
  const double v0 = 2.0, mu = 0.2;
  p.linear_damping = mu * p.gravity / v0;
  auto world = makeWorld(longTable(), p, StepParams{}, {makeBall(kCueBall, {kStartX, 0.0})});
  world->strike(kCueBall, Shot::withSpeed(0.0, v0));
  world->runFor(v0 / (mu * p.gravity));
  EXPECT_GT(length(stateOf(*world, kCueBall).vel), 0.3 * v0);  // exp(-1) = 0.37 of v0
}

}  // namespace
}  // namespace nineball::physics_test
