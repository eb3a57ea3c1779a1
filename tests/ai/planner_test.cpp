// The computer opponent's planner, checked by playing its shots through the real physics.
#include "nineball/planner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "nineball/match.hpp"
#include "rules/ball_list.hpp"

using nineball::BallState;
using nineball::Match;
using nineball::MatchSetup;
using nineball::TurnInput;
using nineball::TurnRecord;
using nineball::Vec2;
using nineball::ai::allLevels;
using nineball::ai::ExecutionNoise;
using nineball::ai::Level;
using nineball::ai::levelFromName;
using nineball::ai::levelName;
using nineball::ai::levelNames;
using nineball::ai::LevelSettings;
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

using nineball::rules::contains;

// The planned shot played as planned (no execution noise).
TurnRecord playPlan(Match& match, const Plan& plan) {
  return match.play(plan.turn);
}

}  // namespace

TEST(Planner, PotsAStraightInShot) {
  // The 1 a little off the top-right corner, the cue ball on the line behind it.
  Match match(layout({ball(0, {0.4, 0.1}), ball(1, {1.0, 0.45}), ball(5, {-0.8, -0.3})}));
  Planner planner(Level::Club, 1);
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
  Planner planner(Level::Casual, 1);
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
  Planner planner(Level::Casual, 1);
  const Plan plan = planner.plan(planInputFrom(match));
  EXPECT_EQ(plan.kind, ShotKind::Break);
  ASSERT_TRUE(plan.turn.cue);
  EXPECT_LE(plan.turn.cue->x, match.world().table().headStringX());
  EXPECT_GE(plan.turn.shot.speed, 6.5) << "a break is a power stroke at every level";
  EXPECT_NO_THROW(match.play(plan.turn));
}

TEST(Planner, PrefersALegalPotToAFoul) {
  // The 2 sits between the cue ball and the 1; the 1 can still be cut into a pocket.
  const std::vector<BallState> balls = {ball(0, {-0.3, -0.2}), ball(1, {0.6, 0.3}),
                                        ball(2, {0.15, 0.05}), ball(3, {0.9, -0.4})};
  for (Level level : {Level::Casual, Level::Club}) {
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
  for (Level level : allLevels()) {
    Planner one(level, 5, 1);
    Planner two(level, 5, 2);
    const Plan a = one.plan(planInputFrom(match));
    const Plan b = two.plan(planInputFrom(match));
    EXPECT_EQ(a.turn.shot.heading_rad, b.turn.shot.heading_rad) << levelName(level);
    EXPECT_EQ(a.turn.shot.speed, b.turn.shot.speed) << levelName(level);
    EXPECT_EQ(a.value, b.value) << levelName(level);
    EXPECT_EQ(a.simulations, b.simulations) << levelName(level);
    const TurnInput ea = one.execute(a);
    const TurnInput eb = two.execute(b);
    EXPECT_EQ(ea.shot.heading_rad, eb.shot.heading_rad) << levelName(level);
    EXPECT_EQ(ea.shot.speed, eb.shot.speed) << levelName(level);
    EXPECT_EQ(ea.shot.tip.x, eb.shot.tip.x) << levelName(level);
  }
}

TEST(Planner, ExecutionNoiseGrowsFromHardToEasy) {
  Match match(layout({ball(0, {0.4, 0.1}), ball(1, {1.0, 0.45})}));
  double spread[3] = {0, 0, 0};
  int i = 0;
  for (Level level : {Level::Master, Level::Club, Level::Casual}) {
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

namespace {

// The standard deviation of the executed heading, degrees, over 4000 strokes of `plan`.
double headingSpreadDeg(Level level, const Plan& plan) {
  Planner planner(level, 11);
  double sum = 0.0;
  constexpr int kDraws = 4000;
  for (int k = 0; k < kDraws; ++k) {
    const double e =
        nineball::radToDeg(planner.execute(plan).shot.heading_rad - plan.turn.shot.heading_rad);
    sum += e * e;
  }
  return std::sqrt(sum / kDraws);
}

}  // namespace

TEST(Planner, EachLevelAimsWorseOnCutsLongShotsAndPowerStrokes) {
  // The stroke model: sd = aim x (1 + cut_growth sin^2 cut) (1 + reach_growth reach) (1 +
  // pace_growth (speed / 2 m/s - 1)). Checked within 5 % (sampling error of an sd from 4000
  // draws: about 1 %), and stronger levels err less on the same stroke.
  Plan easy;
  easy.kind = ShotKind::Pot;
  easy.turn.shot = nineball::Shot::withSpeed(0.0, 1.5);
  Plan hard = easy;
  hard.cut_deg = 60.0;
  hard.reach_m = 2.0;
  hard.turn.shot.speed = 5.0;
  double weaker_sd = 1e9;
  for (Level level : allLevels()) {
    const LevelSettings s = LevelSettings::of(level);
    const double easy_sd = headingSpreadDeg(level, easy);
    const double hard_sd = headingSpreadDeg(level, hard);
    EXPECT_NEAR(easy_sd, s.aim_noise_deg, 0.05 * s.aim_noise_deg) << levelName(level);
    const double growth =
        (1.0 + s.cut_growth * 0.75) * (1.0 + s.reach_growth * 2.0) * (1.0 + s.pace_growth * 1.5);
    EXPECT_NEAR(hard_sd, growth * s.aim_noise_deg, 0.05 * growth * s.aim_noise_deg)
        << levelName(level);
    EXPECT_GT(growth, 1.2) << levelName(level) << ": errors grow with the stroke's difficulty";
    EXPECT_LT(hard_sd, weaker_sd) << levelName(level) << " errs less than the level below";
    weaker_sd = hard_sd;
  }
}

TEST(Planner, APlanCarriesItsCutAndReach) {
  // The cue ball 1 m from the 1 along x: whatever pot it plays, the cut is the angle whose sine
  // is the heading's offset from the 1's centre over two radii (0.01 deg: rounding only).
  Match match(layout({ball(0, {-0.5, 0.0}), ball(1, {0.5, 0.0})}));
  const double r = nineball::PhysicsParams{}.ball_radius;
  Planner planner(Level::Master, 1);
  const Plan plan = planner.plan(planInputFrom(match));
  ASSERT_EQ(plan.first, 1);
  EXPECT_NEAR(plan.reach_m, 1.0 - 2.0 * r, 1e-9);
  const double offset = std::abs(std::sin(plan.turn.shot.heading_rad));
  EXPECT_NEAR(plan.cut_deg, nineball::radToDeg(std::asin(offset / (2.0 * r))), 0.01);
  EXPECT_GT(plan.cut_deg, 1.0) << "a straight pot along x has no pocket: it cuts";
}

TEST(Planner, EveryLevelAndOlderNameIsKnown) {
  ASSERT_EQ(allLevels().size(), 7u);
  for (Level level : allLevels()) EXPECT_EQ(levelFromName(levelName(level)), level);
  EXPECT_EQ(levelFromName("easy"), Level::Casual);
  EXPECT_EQ(levelFromName("medium"), Level::Club);
  EXPECT_EQ(levelFromName("hard"), Level::Master);
  EXPECT_FALSE(levelFromName("Hard"));
  EXPECT_FALSE(levelFromName("grandmaster"));
  EXPECT_EQ(levelNames().size(), 10u);
}

TEST(Planner, UnderTheOlympiadNoiseTheBreakIsJudgedByThatNoise) {
  // Every break candidate is struck 24 times with the tournaments' noise (a controlled 6.5 m/s
  // break among them), from a fixed seed: the same choice on one and two threads.
  MatchSetup setup;
  setup.seed = 3;
  setup.game = nineball::rules::Game::EightBall;
  Match match(setup);
  Planner one(Level::Master, ExecutionNoise::olympiad(), 1, 1);
  Planner two(Level::Master, ExecutionNoise::olympiad(), 1, 2);
  const auto& speeds = one.settings().break_speeds;
  EXPECT_NE(std::find(speeds.begin(), speeds.end(), 6.5), speeds.end());
  const Plan a = one.plan(planInputFrom(match));
  const Plan b = two.plan(planInputFrom(match));
  EXPECT_EQ(a.kind, ShotKind::Break);
  EXPECT_EQ(a.turn.shot.heading_rad, b.turn.shot.heading_rad);
  EXPECT_EQ(a.turn.shot.speed, b.turn.shot.speed);
  EXPECT_EQ(a.value, b.value);
  EXPECT_GE(a.simulations, 24 * 2 * static_cast<int>(speeds.size()));
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
  Planner planner(Level::Casual, 1);
  const TurnInput decision = planner.turnFor(match);
  EXPECT_EQ(decision.kind, TurnInput::Kind::Decision);
  EXPECT_NO_THROW(match.play(decision));
  EXPECT_FALSE(match.rack().awaitingDecision());
}
