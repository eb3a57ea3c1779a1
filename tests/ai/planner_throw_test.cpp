// The planner's aim allowing for squirt and throw, checked by playing the shot through the
// whole physics (the Box2D world) and reading where the object ball leaves for. Tolerance
// 0.01 deg: an object ball 2 m from its pocket then strays 0.35 mm, a hundredth of the pocket's
// margin; the prediction and the world share the models, so what remains is the world's
// contact timing (1 um) and float positions.
#include "ai/planner_throw.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "physics/engines/box2d/world.hpp"

namespace nineball::ai {
namespace {

constexpr double kToleranceDeg = 0.01;

double deg(double rad) {
  return rad * 180.0 / kPi;
}

// The object ball's direction (rad) after the cue ball, struck with `shot`, first meets it;
// nothing when it stops short.
std::optional<double> playedDeparture(const PhysicsParams& p, Vec2 cue, Vec2 object,
                                      const Shot& shot) {
  World world(TableDef{}, p, StepParams{});
  BallState c, o;
  c.id = kCueBall;
  c.pos = cue;
  o.id = 1;
  o.pos = object;
  world.addBall(c);
  world.addBall(o);
  world.strike(kCueBall, shot);
  while (!world.atRest()) {
    world.step();
    for (const Event& e : world.events()) {
      if (e.type == EventType::BallBall) return std::atan2(e.vb.y, e.vb.x);
    }
  }
  return std::nullopt;
}

struct Case {
  double cut_deg, speed;
  Vec2 tip;
};

TEST(PlannerThrow, TheAimAllowingForThrowSendsTheObjectBallWhereItWasMeant) {
  const PhysicsParams p;
  const double r = p.ball_radius;
  const Vec2 cue{-0.6, 0.1}, object{0.2, -0.05};
  double worst_ghost = 0.0, worst_allowed = 0.0;
  int short_of_it = 0, ghost_misses = 0;
  for (double cut : {0.0, 15.0, 30.0, 45.0, 60.0}) {
    for (double speed : {0.7, 1.5, 3.0, 5.0}) {
      for (Vec2 tip : {Vec2{0, 0}, Vec2{0, 0.4}, Vec2{0, -0.4}, Vec2{0.3, 0}, Vec2{-0.25, 0.25}}) {
        // The object ball is sent `cut` to the left of the cue-object line.
        const Vec2 line = normalized(object - cue);
        const Vec2 want = rotated(line, degToRad(cut));
        const Vec2 ghost = object - want * (2.0 * r);
        const double ghost_heading = std::atan2(ghost.y - cue.y, ghost.x - cue.x);
        const double want_rad = std::atan2(want.y, want.x);
        Shot shot;
        shot.speed = speed;
        shot.tip = tip;
        const ThrowSetup s{cue, p.ball_mass, object, p.ball_mass, shot};
        shot.heading_rad = headingAllowingForThrow(p, s, ghost_heading, want_rad);
        const auto played = playedDeparture(p, cue, object, shot);
        shot.heading_rad = ghost_heading;
        const auto ghost_played = playedDeparture(p, cue, object, shot);
        if (!played && !ghost_played) {
          ++short_of_it;  // heavy draw at 0.7 m/s stops short of the ball
          continue;
        }
        ASSERT_TRUE(played) << "cut " << cut << " speed " << speed;
        const double allowed = deg(std::remainder(*played - want_rad, 2.0 * kPi));
        // Squirt alone makes the ghost ball's aim miss a thin cut.
        ghost_misses += ghost_played ? 0 : 1;
        const double ghostly =
            ghost_played ? deg(std::remainder(*ghost_played - want_rad, 2.0 * kPi)) : 0.0;
        EXPECT_LT(std::abs(allowed), kToleranceDeg)
            << "cut " << cut << " speed " << speed << " tip " << tip.x << "," << tip.y;
        worst_ghost = std::max(worst_ghost, std::abs(ghostly));
        worst_allowed = std::max(worst_allowed, std::abs(allowed));
      }
    }
  }
  std::printf(
      "[ measured ] object ball off its line: ghost ball aim up to %.2f deg, "
      "or missing it (%d of 100); allowing for throw up to %.4f deg\n",
      worst_ghost, ghost_misses, worst_allowed);
  EXPECT_LE(short_of_it, 5);
  // Without the allowance the miss is the size of throw: the test would notice it gone.
  EXPECT_GT(worst_ghost, 2.0);
}

TEST(PlannerThrow, FrictionlessBallsNeedNoAllowance) {
  PhysicsParams p = *PhysicsParams::preset("paper");
  const double r = p.ball_radius;
  const Vec2 cue{-0.5, 0.0}, object{0.3, 0.0};
  const Vec2 want = rotated(Vec2{1.0, 0.0}, degToRad(35.0));
  const Vec2 ghost = object - want * (2.0 * r);
  const double ghost_heading = std::atan2(ghost.y - cue.y, ghost.x - cue.x);
  Shot shot;
  shot.speed = 2.0;
  const ThrowSetup s{cue, p.ball_mass, object, p.ball_mass, shot};
  EXPECT_NEAR(headingAllowingForThrow(p, s, ghost_heading, std::atan2(want.y, want.x)),
              ghost_heading, 1e-9);
}

TEST(PlannerThrow, AMissedBallLeavesTheAimAlone) {
  const PhysicsParams p;
  Shot shot;
  shot.speed = 2.0;
  const ThrowSetup s{{-0.5, 0.0}, p.ball_mass, {0.3, 0.0}, p.ball_mass, shot};
  EXPECT_FALSE(objectDeparture(p, s, degToRad(90.0)));
  EXPECT_EQ(headingAllowingForThrow(p, s, degToRad(90.0), 0.0), degToRad(90.0));
}

}  // namespace
}  // namespace nineball::ai
