// The computer's jump shots: the strongest levels jump a ball in the way, the rest kick, and
// snooker (where a jump shot is a foul) never jumps. Played through the real physics.
#include "ai/planner_jump.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "nineball/match.hpp"
#include "nineball/planner.hpp"
#include "rules/ball_list.hpp"

using nineball::BallState;
using nineball::Match;
using nineball::MatchSetup;
using nineball::TurnRecord;
using nineball::Vec2;
using nineball::ai::Level;
using nineball::ai::levelName;
using nineball::ai::Plan;
using nineball::ai::planInputFrom;
using nineball::ai::Planner;
using nineball::ai::ShotKind;
using nineball::rules::contains;

namespace {

// The 1 on its line to the top-right corner, the cue ball behind it and the 2 on the line
// between them: the straight pot only by jumping the 2. The 3 and the 4 close the other lines.
std::vector<BallState> blockedPot() {
  return {BallState::at(0, {-0.2, -0.35}), BallState::at(2, {0.12, -0.15}),
          BallState::at(1, {0.75, 0.24}),  BallState::at(3, {0.55, 0.45}),
          BallState::at(4, {0.95, 0.05}),  BallState::at(9, {-0.9, 0.4})};
}

}  // namespace

TEST(PlannerJump, JumpStrokesClearTheBlockerAndLandBeforeTheBallOn) {
  const nineball::PhysicsParams p = nineball::PhysicsParams::real();
  const std::vector<BallState> balls = blockedPot();
  const Vec2 cue = balls[0].pos;
  const Vec2 on = balls[2].pos;
  const double heading = std::atan2(on.y - cue.y, on.x - cue.x);
  const double land_by = nineball::length(on - cue) - 2.0 * p.ball_radius;
  const auto blockers = nineball::ai::ballsInTheWay(balls, cue, heading, land_by, p.ball_radius, 1);
  ASSERT_EQ(blockers.size(), 1u);
  EXPECT_EQ(blockers[0]->id, 2);
  const auto strokes = nineball::ai::jumpStrokes(p, cue, heading, blockers, land_by);
  ASSERT_FALSE(strokes.empty());
  for (const auto& s : strokes) {
    EXPECT_LE(s.lands_at, land_by);
    EXPECT_GT(s.lands_at, nineball::length(blockers[0]->pos - cue));
  }
  // Nothing in the way: nothing to jump.
  EXPECT_TRUE(nineball::ai::jumpStrokes(p, cue, heading, {}, land_by).empty());
}

TEST(PlannerJump, TheStrongestLevelsJumpTheBlockerAndPot) {
  for (Level level : {Level::Pro, Level::Master}) {
    MatchSetup setup;
    setup.balls = blockedPot();
    Match m(setup);
    Planner planner(level, 1);
    const Plan plan = planner.plan(planInputFrom(m));
    EXPECT_EQ(plan.kind, ShotKind::Jump) << levelName(level);
    EXPECT_EQ(plan.target, 1) << levelName(level);
    EXPECT_GT(plan.turn.shot.elevation_rad, 0.0) << levelName(level);
    const TurnRecord r = m.play(plan.turn);
    EXPECT_TRUE(r.verdict.legal()) << levelName(level);
    EXPECT_TRUE(contains(r.verdict.pocketed, 1)) << levelName(level);
  }
}

TEST(PlannerJump, LowerLevelsNeverJump) {
  for (Level level :
       {Level::Beginner, Level::Casual, Level::Club, Level::League, Level::Advanced}) {
    MatchSetup setup;
    setup.balls = blockedPot();
    Match m(setup);
    Planner planner(level, 1);
    const Plan plan = planner.plan(planInputFrom(m));
    EXPECT_NE(plan.kind, ShotKind::Jump) << levelName(level);
    EXPECT_EQ(plan.turn.shot.elevation_rad, 0.0) << levelName(level);
  }
}

TEST(PlannerJump, SnookerNeverJumpsForItIsAFoul) {
  // The red on its line to the top-right corner, the blue on the cue ball's line to it.
  MatchSetup setup;
  setup.setGame(nineball::rules::Game::Snooker);
  setup.balls = {BallState::at(0, {0.6, -0.07}), BallState::at(19, {0.95, 0.22}),
                 BallState::at(1, {1.3, 0.5}), BallState::at(21, {-1.2, 0.0})};
  Match m(setup);
  Planner planner(Level::Master, 1);
  const Plan plan = planner.plan(planInputFrom(m));
  EXPECT_NE(plan.kind, ShotKind::Jump);
  EXPECT_EQ(plan.turn.shot.elevation_rad, 0.0);
}
