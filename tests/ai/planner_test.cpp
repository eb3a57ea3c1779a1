// The computer opponent's planner, checked by playing its shots through the real physics.
#include "nineball/planner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "nineball/match.hpp"

using nineball::BallState;
using nineball::Match;
using nineball::MatchSetup;
using nineball::TurnInput;
using nineball::TurnRecord;
using nineball::Vec2;
using nineball::ai::ExecutionNoise;
using nineball::ai::Level;
using nineball::ai::Plan;
using nineball::ai::planInputFrom;
using nineball::ai::Planner;
using nineball::ai::ShotKind;

namespace {

BallState ball(int id, Vec2 p) {
  BallState b;
  b.id = id;
  b.pos = p;
  return b;
}

MatchSetup layout(std::vector<BallState> balls) {
  MatchSetup s;
  s.balls = std::move(balls);
  return s;
}

bool contains(const std::vector<int>& v, int x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

// The planned shot played as planned (no execution noise).
TurnRecord playPlan(Match& match, const Plan& plan) {
  return match.play(plan.turn);
}

}  // namespace

TEST(Planner, PotsAStraightInShot) {
  // The 1 a little off the top-right corner, the cue ball on the line behind it.
  Match match(layout({ball(0, {0.4, 0.1}), ball(1, {1.0, 0.45}), ball(5, {-0.8, -0.3})}));
  Planner planner(Level::Medium, 1);
  const Plan plan = planner.plan(planInputFrom(match));
  EXPECT_EQ(plan.kind, ShotKind::Pot);
  EXPECT_EQ(plan.target, 1);
  EXPECT_GT(plan.value, 0.55);
  EXPECT_FALSE(plan.turn.cue);
  const TurnRecord r = playPlan(match, plan);
  EXPECT_TRUE(r.verdict.legal());
  EXPECT_TRUE(contains(r.verdict.pocketed, 1));
}

TEST(Planner, PlacesTheCueBallLegallyWithBallInHand) {
  MatchSetup setup = layout({ball(2, {0.3, -0.2}), ball(3, {-0.5, 0.3}), ball(9, {0.9, 0.1})});
  Match match(setup);  // no cue ball: it is in hand
  ASSERT_TRUE(match.cueInHand());
  Planner planner(Level::Easy, 1);
  const Plan plan = planner.plan(planInputFrom(match));
  ASSERT_TRUE(plan.turn.cue);
  EXPECT_FALSE(match.cuePlacementProblem(*plan.turn.cue))
      << *match.cuePlacementProblem(*plan.turn.cue);
  const TurnRecord r = playPlan(match, plan);
  EXPECT_TRUE(r.verdict.legal());
}

TEST(Planner, BreaksFromBehindTheHeadString) {
  MatchSetup setup;
  setup.seed = 3;
  Match match(setup);
  Planner planner(Level::Easy, 1);
  const Plan plan = planner.plan(planInputFrom(match));
  EXPECT_EQ(plan.kind, ShotKind::Break);
  ASSERT_TRUE(plan.turn.cue);
  EXPECT_LE(plan.turn.cue->x, match.world().table().headStringX());
  EXPECT_GE(plan.turn.shot.speed, 9.0);
  EXPECT_NO_THROW(match.play(plan.turn));
}

TEST(Planner, PrefersALegalPotToAFoul) {
  // The 2 sits between the cue ball and the 1; the 1 can still be cut into a pocket.
  const std::vector<BallState> balls = {ball(0, {-0.3, -0.2}), ball(1, {0.6, 0.3}),
                                        ball(2, {0.15, 0.05}), ball(3, {0.9, -0.4})};
  for (Level level : {Level::Easy, Level::Medium}) {
    Match match(layout(balls));
    Planner planner(level, 1);
    const Plan plan = planner.plan(planInputFrom(match));
    const TurnRecord r = playPlan(match, plan);
    EXPECT_TRUE(r.verdict.legal())
        << nineball::ai::levelName(level) << ": " << nineball::rules::foulName(r.verdict.foul);
  }
}

TEST(Planner, TheSameInputGivesTheSamePlanOnOneOrTwoThreads) {
  Match match(layout(
      {ball(0, {-0.6, 0.2}), ball(3, {0.2, -0.1}), ball(4, {0.7, 0.35}), ball(9, {-0.1, 0.4})}));
  Planner one(Level::Medium, 5, 1);
  Planner two(Level::Medium, 5, 2);
  const Plan a = one.plan(planInputFrom(match));
  const Plan b = two.plan(planInputFrom(match));
  EXPECT_EQ(a.turn.shot.heading_rad, b.turn.shot.heading_rad);
  EXPECT_EQ(a.turn.shot.speed, b.turn.shot.speed);
  EXPECT_EQ(a.value, b.value);
  EXPECT_EQ(a.simulations, b.simulations);
  const TurnInput ea = one.execute(a);
  const TurnInput eb = two.execute(b);
  EXPECT_EQ(ea.shot.heading_rad, eb.shot.heading_rad);
  EXPECT_EQ(ea.shot.speed, eb.shot.speed);
}

TEST(Planner, ExecutionNoiseGrowsFromHardToEasy) {
  Match match(layout({ball(0, {0.4, 0.1}), ball(1, {1.0, 0.45})}));
  double spread[3] = {0, 0, 0};
  int i = 0;
  for (Level level : {Level::Hard, Level::Medium, Level::Easy}) {
    Planner planner(level, 11);
    Plan plan;
    plan.turn.shot = nineball::Shot::withSpeed(30.0, 2.0);
    for (int k = 0; k < 200; ++k) {
      spread[i] += std::abs(planner.execute(plan).shot.heading_rad - plan.turn.shot.heading_rad);
    }
    ++i;
  }
  EXPECT_LT(spread[0], spread[1]);
  EXPECT_LT(spread[1], spread[2]);
}

TEST(Planner, TheOlympiadNoiseIsTheTournamentsGaussian) {
  // 0.1 deg of aim, 0.125 deg of elevation, 0.075 m/s, 0.5 mm of each tip offset, on every
  // shot; measured over 4000 executions, each deviation within 5 % (the sampling error of a
  // standard deviation from 4000 draws is about 1 %).
  Planner planner(Level::Hard, ExecutionNoise::olympiad(), 7);
  Plan plan;
  plan.kind = ShotKind::Break;  // the break too: no softening
  plan.turn.shot = nineball::Shot::withSpeed(30.0, 5.0);
  plan.turn.shot.elevation_rad = nineball::degToRad(10.0);
  double aim = 0, speed = 0, elevation = 0, tip_x = 0, tip_y = 0;
  constexpr int kDraws = 4000;
  for (int k = 0; k < kDraws; ++k) {
    const nineball::Shot s = planner.execute(plan).shot;
    const auto sq = [](double v) { return v * v; };
    aim += sq(nineball::radToDeg(s.heading_rad - plan.turn.shot.heading_rad));
    speed += sq(s.speed - 5.0);
    elevation += sq(nineball::radToDeg(s.elevation_rad) - 10.0);
    tip_x += sq(s.tip.x * nineball::PhysicsParams{}.ball_radius);
    tip_y += sq(s.tip.y * nineball::PhysicsParams{}.ball_radius);
  }
  const auto sd = [&](double sum) { return std::sqrt(sum / kDraws); };
  EXPECT_NEAR(sd(aim), 0.1, 0.005);
  EXPECT_NEAR(sd(speed), 0.075, 0.00375);
  EXPECT_NEAR(sd(elevation), 0.125, 0.00625);
  EXPECT_NEAR(sd(tip_x), 0.0005, 0.000025);
  EXPECT_NEAR(sd(tip_y), 0.0005, 0.000025);
}

TEST(Planner, DecidesAfterTheOpponentsPushOut) {
  MatchSetup setup;
  setup.seed = 1;
  Match match(setup);
  TurnInput soft_break;
  soft_break.shot = nineball::Shot::withSpeed(0.0, 6.0);
  ASSERT_TRUE(match.play(soft_break).verdict.legal());
  TurnInput push;
  push.kind = TurnInput::Kind::PushOut;
  push.shot = nineball::Shot::withSpeed(90.0, 0.3);
  match.play(push);
  ASSERT_TRUE(match.rack().awaitingDecision());
  Planner planner(Level::Easy, 1);
  const TurnInput decision = planner.turnFor(match);
  EXPECT_EQ(decision.kind, TurnInput::Kind::Decision);
  EXPECT_NO_THROW(match.play(decision));
  EXPECT_FALSE(match.rack().awaitingDecision());
}
