// The computer's snooker (src/ai/snooker_value.cpp, snooker_decision.cpp): colours re-spotted on
// their own spots in the planner's outcomes, a score that takes the higher colour at equal
// position, prefers a snooker to an open leave and a small penalty to a large one, and a pending
// foul answered with a choice the match takes.
#include <gtest/gtest.h>

#include <cmath>

#include "ai/planner_evaluate.hpp"
#include "games/snooker/spots.hpp"
#include "nineball/match.hpp"
#include "nineball/planner.hpp"
#include "nineball/table_markings.hpp"

namespace nineball::ai {
namespace {

constexpr int kRed = 1;
constexpr int kBlue = 19;
constexpr int kBlack = 21;

Match snookerMatch(std::vector<BallState> balls) {
  MatchSetup setup;
  setup.setGame(rules::Game::Snooker);
  setup.balls = std::move(balls);
  return Match(setup);
}

Outcome outcomeOf(const PlanInput& in, std::vector<BallState> balls, bool legal, int points) {
  Outcome o{std::move(balls), in.rack, {}, false};
  const rules::Player me = in.rack.shooter();
  const rules::Player them = me == rules::Player::A ? rules::Player::B : rules::Player::A;
  o.verdict.shooter = me;
  if (legal) {
    o.verdict.next = points > 0 ? me : them;
    o.verdict.points[me == rules::Player::A ? 0 : 1] = points;
  } else {
    o.verdict.foul = rules::Foul::PottedNotOn;
    o.verdict.next = them;
    o.verdict.points[them == rules::Player::A ? 0 : 1] = points;
  }
  return o;
}

TEST(SnookerValue, APottedColourIsReSpottedOnItsOwnSpot) {
  // On a red, the black is potted into the top corner: a foul, and the black goes back on the
  // black spot (WPBSA 3.7), not on pool's foot spot.
  const Match match =
      snookerMatch({BallState::at(0, {1.2, 0.6}), BallState::at(kBlack, {1.5, 0.75}),
                    BallState::at(kRed, {-1.0, -0.5})});
  const PlanInput in = planInputFrom(match);
  const TableGeometry table = buildTable(in.table, in.physics.ball_radius);
  const Evaluator eval(in, table);
  Candidate c;
  c.kind = ShotKind::Pot;
  c.shot.heading_rad = std::atan2(0.15, 0.3);
  c.shot.speed = 2.0;
  const std::optional<Outcome> o = eval.outcome(c, c.shot);
  ASSERT_TRUE(o);
  ASSERT_EQ(o->verdict.to_spot, std::vector<int>{kBlack}) << "the black must drop for this test";
  EXPECT_FALSE(o->verdict.legal());
  const Vec2 spot = snooker::colourSpot(in.table, kBlack);
  bool found = false;
  for (const BallState& b : o->balls) {
    if (b.id != kBlack) continue;
    found = true;
    EXPECT_FALSE(b.pocket);
    EXPECT_NEAR(b.pos.x, spot.x, 1e-9);
    EXPECT_NEAR(b.pos.y, spot.y, 1e-9);
  }
  EXPECT_TRUE(found);
  EXPECT_GT(std::abs(table.footSpot().x - spot.x), 0.1) << "the spots must differ for this test";
}

TEST(SnookerValue, TheHigherColourTheSmallerPenaltyAndTheSnookerScoreMore) {
  const std::vector<BallState> snookered{BallState::at(0, {-1.0, 0.0}),
                                         BallState::at(kBlue, {-0.7, 0.0}),
                                         BallState::at(kRed, {-0.3, 0.0})};
  std::vector<BallState> open = snookered;
  open[1].pos = {-0.7, 0.6};  // the blue aside: the red in a straight line from the cue ball
  const Match match = snookerMatch(snookered);
  const PlanInput in = planInputFrom(match);
  const TableGeometry table = buildTable(in.table, in.physics.ball_radius);
  const Evaluator eval(in, table);

  const double black = eval.score(outcomeOf(in, open, true, 7));
  const double yellow = eval.score(outcomeOf(in, open, true, 2));
  EXPECT_GT(black, yellow) << "the same position after the black is worth more";
  EXPECT_GE(yellow, kContinueBase);
  EXPECT_LT(black, 1.0);

  const double snooker = eval.score(outcomeOf(in, snookered, true, 0));
  const double open_leave = eval.score(outcomeOf(in, open, true, 0));
  EXPECT_GT(snooker, open_leave) << "a snooker is the best leave";
  EXPECT_LT(snooker, kContinueBase);

  const double four_away = eval.score(outcomeOf(in, open, false, 4));
  const double seven_away = eval.score(outcomeOf(in, open, false, 7));
  EXPECT_GT(four_away, seven_away) << "a foul giving away 7 is worse than one giving away 4";
  EXPECT_LE(four_away, kFoulValueTop);
  EXPECT_LT(four_away, open_leave) << "every foul is below every legal shot";
}

TEST(SnookerValue, AFoulIsAnsweredWithAChoiceTheMatchTakes) {
  MatchSetup setup;
  setup.setGame(rules::Game::Snooker);
  Match match(setup);
  // The break-off played away from every ball, softly into the baulk cushion: a foul (and a
  // miss), and the opponent chooses.
  TurnInput foul;
  foul.cue =
      Vec2{SnookerLayout::of(match.world().table().def).baulk_x - 0.1, 0.15};  // clear of the brown
  foul.shot.heading_rad = std::acos(-1.0);
  foul.shot.speed = 0.8;
  const TurnRecord r = match.play(foul);
  ASSERT_FALSE(r.verdict.legal());
  ASSERT_TRUE(match.rack().awaitingDecision());
  const rules::Player chooser = match.rack().shooter();
  Planner planner(Level::Casual, 1, 1);
  const TurnInput answer = planner.turnFor(match);
  EXPECT_EQ(answer.kind, TurnInput::Kind::Decision);
  const TurnRecord taken = match.play(answer);
  EXPECT_FALSE(match.rack().awaitingDecision());
  // Playing on keeps the chooser at the table; a put-back or a replace gives it to the offender.
  EXPECT_EQ(match.rack().shooter() == chooser, answer.shoot && !answer.replace);
  EXPECT_EQ(taken.replace, answer.replace);
}

}  // namespace
}  // namespace nineball::ai
