// The public closed forms of free motion (nineball/motion.hpp): the phases a ball passes
// through, against the paper's and Alciatore's closed forms, and the contact time against the
// reference engine, which finds the same contact as an event of a whole run.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "nineball/engine.hpp"
#include "nineball/motion.hpp"

namespace nineball {
namespace {

// A stun shot (no spin) slides until v = 5/7 v0, after t = 2 v0 / (7 mu_s g), then rolls with
// the rolling resistance until it stops: s = v^2 / (2 mu_r g). Rounding only: 1e-9.
TEST(FreeMotion, AStunBallSlidesThenRollsThenStopsAsTheClosedFormsSay) {
  const PhysicsParams p;
  const double v0 = 2.0;
  const BallState ball = BallState::at(0, {}, {v0, 0.0});
  const double t_roll = 2.0 * v0 / (7.0 * p.sliding_friction * p.gravity);
  const BallState rolling = freeMotion(ball, t_roll, p);
  EXPECT_NEAR(rolling.vel.x, 5.0 / 7.0 * v0, 1e-9);
  EXPECT_NEAR(rolling.w.y, rolling.vel.x / p.ball_radius, 1e-9);
  const double v1 = 5.0 / 7.0 * v0;
  const double t_stop = t_roll + v1 / (p.rolling_friction * p.gravity);
  const double slide = v0 * t_roll - 0.5 * p.sliding_friction * p.gravity * t_roll * t_roll;
  const double roll = v1 * v1 / (2.0 * p.rolling_friction * p.gravity);
  const BallState stopped = freeMotion(ball, t_stop + 1.0, p);
  EXPECT_NEAR(stopped.pos.x, slide + roll, 1e-9);
  EXPECT_EQ(stopped.vel.x, 0.0);
  // Later instants follow on from earlier ones.
  const BallState half = freeMotion(ball, 0.5 * t_stop, p);
  EXPECT_NEAR(freeMotion(half, 0.5 * t_stop, p).pos.x, freeMotion(ball, t_stop, p).pos.x, 1e-9);
  EXPECT_THROW(freeMotion(ball, -1.0, p), std::invalid_argument);
}

// The phase a trace names, for a ball in each: struck without spin it slides, after the
// sliding time it rolls, once stopped it rests; side spin alone spins it in place.
TEST(FreeMotion, ThePhaseIsTheOneTheBallIsIn) {
  const PhysicsParams p;
  const double v0 = 2.0;
  const BallState ball = BallState::at(0, {}, {v0, 0.0});
  const double t_roll = 2.0 * v0 / (7.0 * p.sliding_friction * p.gravity);
  EXPECT_EQ(freePhase(ball, p), TracePhase::Sliding);
  EXPECT_EQ(freePhase(freeMotion(ball, 0.5 * t_roll, p), p), TracePhase::Sliding);
  EXPECT_EQ(freePhase(freeMotion(ball, 1.5 * t_roll, p), p), TracePhase::Rolling);
  EXPECT_EQ(freePhase(freeMotion(ball, 100.0, p), p), TracePhase::Rest);
  BallState spinning = BallState::at(0, {});
  spinning.w = {0.0, 0.0, 20.0};
  EXPECT_EQ(freePhase(spinning, p), TracePhase::Spinning);
}

TEST(FreeMotion, TheContactTimeIsTheReferenceEnginesFirstContact) {
  PhysicsParams p;
  StepParams step;
  step.engine = EngineKind::named("reference");
  for (const double spin : {-30.0, 0.0, 40.0}) {
    BallState cue = BallState::at(0, {-0.6, 0.0}, {1.5, 0.02});
    cue.w = {0.0, spin, 5.0};
    const BallState object = BallState::at(1, {0.3, 0.03});
    const auto t = timeToTouch(cue, object, p, 10.0);
    ASSERT_TRUE(t) << spin;
    auto engine = makeEngine(TableDef{}, p, step);
    engine->addBall(cue);
    engine->addBall(object);
    engine->runUntilRest();
    double first = -1.0;
    for (const Event& e : engine->events()) {
      if (e.type == EventType::BallBall) {
        first = e.t;
        break;
      }
    }
    EXPECT_NEAR(*t, first, 1e-9) << spin;
  }
  // Balls moving apart never touch; a horizon too short sees nothing.
  EXPECT_FALSE(timeToTouch(BallState::at(0, {}, {-1.0, 0.0}), BallState::at(1, {0.2, 0.0}), p, 5));
  EXPECT_FALSE(timeToTouch(BallState::at(0, {}, {1.0, 0.0}), BallState::at(1, {0.5, 0.0}), p, 0.1));
}

}  // namespace
}  // namespace nineball
