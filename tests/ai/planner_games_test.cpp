// The computer in eight-ball and ten-ball: its targets, calls and push-outs, its look one shot
// ahead, and whole racks between two computers played to the end through the real physics.
#include <gtest/gtest.h>

#include <algorithm>

#include "ai/planner_lookahead.hpp"
#include "nineball/match.hpp"
#include "nineball/planner.hpp"
#include "rules/ball_list.hpp"

using nineball::BallState;
using nineball::IllegalAction;
using nineball::Match;
using nineball::MatchSetup;
using nineball::TurnInput;
using nineball::TurnRecord;
using nineball::Vec2;
using nineball::ai::Level;
using nineball::ai::Plan;
using nineball::ai::PlanInput;
using nineball::ai::planInputFrom;
using nineball::ai::Planner;
using nineball::ai::ShotKind;
namespace rules = nineball::rules;

namespace {

MatchSetup layout(rules::Game game, std::vector<BallState> balls) {
  MatchSetup s;
  s.game = game;
  s.balls = std::move(balls);
  return s;
}

using nineball::rules::contains;

// A legal break that pocketed `down` and left the breaker at the table.
rules::Rack afterBreak(rules::Game game, std::vector<int> racked, std::vector<int> down) {
  rules::Rack rack(game, rules::RuleSet::Wpa, racked, true);
  rules::ShotSummary s;
  s.first_contact = 1;
  s.pocketed = down;
  s.rail_after_contact = true;
  s.object_balls_to_rail = 4;
  const rules::Verdict v = rack.shoot(s);
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.next, rules::Player::A);
  return rack;
}

PlanInput inputWith(const rules::Rack& rack, std::vector<BallState> balls) {
  PlanInput in;
  in.balls = std::move(balls);
  in.rack = rack;
  return in;
}

}  // namespace

TEST(PlannerEightBall, PotsItsOwnGroupAndNeverHitsTheOtherFirst) {
  // A holds the stripes: the solid 3 is a hanger, the stripe 12 a fair cut.
  Match match(layout(rules::Game::EightBall,
                     {BallState::at(0, {0.3, 0.0}), BallState::at(3, {1.15, 0.55}),
                      BallState::at(12, {0.75, -0.3}), BallState::at(8, {-0.8, 0.3}),
                      BallState::at(2, {-0.5, -0.4})}));
  Planner planner(Level::Master, 1);
  const Plan open = planner.plan(planInputFrom(match));
  EXPECT_NE(open.first, 8) << "the 8 may not be hit first on an open table";
  EXPECT_TRUE(open.kind == ShotKind::Pot || open.kind == ShotKind::Combination ||
              open.kind == ShotKind::Bank);

  // Now the same table with the groups set: A has the stripes.
  rules::Rack rack(rules::Game::EightBall, rules::RuleSet::Wpa, {2, 3, 8, 11, 12}, false);
  rules::ShotSummary pot11;
  pot11.first_contact = 11;
  pot11.pocketed = {11};
  pot11.rail_after_contact = true;
  ASSERT_TRUE(rack.shoot(pot11).legal());
  ASSERT_EQ(rack.groups().a, rules::Group::Stripes);
  const PlanInput in =
      inputWith(rack, {BallState::at(0, {0.3, 0.0}), BallState::at(3, {1.15, 0.55}),
                       BallState::at(12, {0.75, -0.3}), BallState::at(8, {-0.8, 0.3}),
                       BallState::at(2, {-0.5, -0.4})});
  const Plan plan = planner.plan(in);
  EXPECT_EQ(plan.first, 12);
  EXPECT_EQ(plan.target, 12);
  EXPECT_FALSE(plan.turn.call) << "eight-ball calls only the 8";
}

TEST(PlannerEightBall, CallsTheEightWhereItMeansToPotIt) {
  // Solids cleared: only the 8 is left for A.
  Match match(
      layout(rules::Game::EightBall, {BallState::at(0, {0.4, 0.1}), BallState::at(8, {1.0, 0.45}),
                                      BallState::at(13, {-0.8, -0.3})}));
  rules::Rack rack(rules::Game::EightBall, rules::RuleSet::Wpa, {1, 8, 13}, false);
  rules::ShotSummary pot1;
  pot1.first_contact = 1;
  pot1.pocketed = {1};
  pot1.rail_after_contact = true;
  ASSERT_TRUE(rack.shoot(pot1).legal());
  ASSERT_TRUE(rack.callRequired());
  PlanInput in = planInputFrom(match);
  in.rack = rack;
  Planner planner(Level::Club, 1);
  const Plan plan = planner.plan(in);
  EXPECT_EQ(plan.kind, ShotKind::Pot);
  ASSERT_TRUE(plan.turn.call);
  EXPECT_EQ(plan.turn.call->ball, 8);
  ASSERT_TRUE(plan.pocket);
  EXPECT_EQ(plan.turn.call->pocket, *plan.pocket);
}

TEST(PlannerTenBall, EveryShotAfterTheBreakIsCalledAndTheMatchTakesIt) {
  Match match(layout(rules::Game::TenBall,
                     {BallState::at(0, {0.4, 0.1}), BallState::at(1, {1.0, 0.45}),
                      BallState::at(4, {-0.6, 0.2}), BallState::at(10, {-0.8, -0.3})}));
  ASSERT_TRUE(match.rack().callRequired());
  Planner planner(Level::Club, 1);
  const Plan plan = planner.plan(planInputFrom(match));
  ASSERT_TRUE(plan.turn.call);
  EXPECT_EQ(plan.turn.call->ball, plan.target);
  ASSERT_TRUE(plan.pocket);
  EXPECT_EQ(plan.turn.call->pocket, *plan.pocket);
  const TurnRecord r = match.play(plan.turn);
  EXPECT_TRUE(r.verdict.legal());
  EXPECT_EQ(r.verdict.call_breach, rules::Foul::None);
  EXPECT_TRUE(contains(r.verdict.pocketed, 1));
}

TEST(PlannerPushOut, PushesOutWhenTheBallOnIsHiddenAndNotWhenItHangs) {
  const rules::Rack rack = afterBreak(rules::Game::NineBall, {1, 2, 3, 4, 5, 6, 7, 8, 9}, {5});
  ASSERT_TRUE(rack.pushOutAvailable());
  // The 1 frozen in the middle of the foot rail behind a wall of balls; the cue ball at the
  // head rail, both long rails guarded.
  const PlanInput hidden =
      inputWith(rack, {BallState::at(0, {-1.1, 0.0}), BallState::at(1, {1.237, 0.0}),
                       BallState::at(2, {1.17, 0.07}), BallState::at(3, {1.17, -0.07}),
                       BallState::at(4, {1.11, 0.0}), BallState::at(6, {0.4, 0.55}),
                       BallState::at(7, {0.4, -0.55}), BallState::at(8, {-0.4, 0.55}),
                       BallState::at(9, {-0.4, -0.55})});
  Planner planner(Level::Club, 1);
  const Plan push = planner.plan(hidden);
  EXPECT_EQ(push.kind, ShotKind::PushOut) << nineball::ai::shotKindName(push.kind);
  EXPECT_EQ(push.turn.kind, TurnInput::Kind::PushOut);
  EXPECT_FALSE(push.turn.call);
  EXPECT_LE(push.value, 0.5) << "a push-out gives the opponent the better of two choices";

  const PlanInput hanger =
      inputWith(rack, {BallState::at(0, {0.4, 0.1}), BallState::at(1, {1.0, 0.45}),
                       BallState::at(2, {-0.6, 0.2}), BallState::at(3, {-0.8, -0.3}),
                       BallState::at(4, {-0.2, -0.4}), BallState::at(6, {0.2, 0.3}),
                       BallState::at(7, {0.5, -0.5}), BallState::at(8, {-1.0, 0.4}),
                       BallState::at(9, {0.0, -0.1})});
  const Plan pot = planner.plan(hanger);
  EXPECT_EQ(pot.kind, ShotKind::Pot);
  EXPECT_EQ(pot.turn.kind, TurnInput::Kind::Shot);
}

TEST(PlannerLookAhead, SimulatesTheNextShotOnlyWhenTheTableIsKept) {
  rules::Rack rack(rules::Game::NineBall, rules::RuleSet::Wpa, {1, 2, 9}, false);
  const PlanInput in =
      inputWith(rack, {BallState::at(0, {0.4, 0.1}), BallState::at(1, {1.0, 0.45}),
                       BallState::at(2, {0.3, 0.4}), BallState::at(9, {-0.8, -0.3})});
  const nineball::TableGeometry table = nineball::buildTable(in.table, in.physics.ball_radius);
  const nineball::ai::LevelSettings level = nineball::ai::LevelSettings::of(Level::Master);
  const nineball::ai::Evaluator eval(in, table);
  const nineball::ai::SearchContext ctx{in, table, level, in.physics.ball_radius, {1}};

  nineball::ai::Candidate pot;  // a draw shot straight into the top-right corner
  pot.kind = ShotKind::Pot;
  pot.shot.heading_rad = std::atan2(0.35, 0.6);
  pot.shot.speed = 2.5;
  pot.shot.tip = {0.0, -0.4};
  const double geometric = eval.value(pot);
  ASSERT_GE(geometric, nineball::ai::kContinueBase) << "the pot must drop for this test";
  const nineball::ai::LookAhead ahead = nineball::ai::lookAhead(ctx, eval, pot);
  EXPECT_GT(ahead.simulations, 1);
  EXPECT_GT(ahead.value, nineball::ai::kContinueBase) << "the 2 is open from where it stops";
  EXPECT_LE(ahead.value, 1.0);

  nineball::ai::Candidate miss = pot;  // far off the 1: nothing kept, nothing looked at
  miss.shot.heading_rad += 0.6;
  const nineball::ai::LookAhead none = nineball::ai::lookAhead(ctx, eval, miss);
  EXPECT_EQ(none.simulations, 1);
  EXPECT_EQ(none.value, eval.value(miss));
}

namespace {

// Two computers play a whole rack; the rack must end with a winner within the turn limit,
// and every turn the planners give must be one the match takes.
void playOut(rules::Game game, std::uint64_t seed) {
  MatchSetup setup;
  setup.game = game;
  setup.seed = seed;
  Match match(setup);
  Planner a(Level::Club, seed, 2);
  Planner b(Level::Casual, seed + 7, 2);
  int turns = 0;
  while (!match.rack().over() && turns < 300) {
    Planner& p = match.rack().shooter() == rules::Player::A ? a : b;
    const TurnInput turn = p.turnFor(match);
    try {
      match.play(turn);
    } catch (const IllegalAction& e) {
      FAIL() << rules::gameName(game) << " seed " << seed << " turn " << turns << ": " << e.what();
    }
    ++turns;
  }
  EXPECT_TRUE(match.rack().over())
      << rules::gameName(game) << " seed " << seed << " after " << turns << " turns";
}

}  // namespace

TEST(PlannerRacks, TwoComputersFinishEightBallRacks) {
  for (std::uint64_t seed : {1, 2}) playOut(rules::Game::EightBall, seed);
}

TEST(PlannerRacks, TwoComputersFinishTenBallRacks) {
  for (std::uint64_t seed : {1, 2}) playOut(rules::Game::TenBall, seed);
}
