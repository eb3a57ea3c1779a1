// Snooker played through the real physics: the cue ball in hand in the D, colours re-spotted
// by the match, the free ball judged from the balls' rest positions, a miss replaced. On the
// game's own equipment: the "snooker" table and physics preset.
#include <gtest/gtest.h>

#include "games/snooker/spots.hpp"
#include "nineball/match.hpp"
#include "nineball/snooker_rack.hpp"
#include "nineball/table_markings.hpp"
#include "play/match_turns.hpp"

namespace nineball {
namespace {

using play_test::decision;
using play_test::shot;
using play_test::where;
using rules::Game;
using rules::Player;

const TableDef kTable = TableDef::snooker();

MatchSetup snookerSetup(std::optional<std::vector<BallState>> balls = std::nullopt) {
  MatchSetup s;
  s.setGame(Game::Snooker);
  s.balls = std::move(balls);
  return s;
}

TEST(MatchSnooker, TheGameBringsItsOwnTableAndPreset) {
  const MatchSetup s = snookerSetup();
  EXPECT_EQ(s.rules, rules::RuleSet::Wpbsa);
  EXPECT_EQ(s.table.length, 3.569);
  EXPECT_EQ(s.table.marks, TableMarks::Snooker);
  EXPECT_EQ(s.physics.ball_radius, PhysicsParams::preset("snooker")->ball_radius);
}

TEST(MatchSnooker, TheOpeningStrokeIsPlayedFromHandInTheD) {
  Match m(snookerSetup());
  EXPECT_TRUE(m.cueInHand());
  EXPECT_EQ(m.cueArea(), CueArea::TheD);
  EXPECT_FALSE(m.cueBehindHeadString());
  const double xb = SnookerLayout::of(kTable).baulk_x;
  try {
    m.play(shot(0.0, 3.0));
    FAIL() << "a stroke without placing the cue ball";
  } catch (const IllegalAction& e) {
    EXPECT_NE(std::string(e.what()).find("in the D"), std::string::npos) << e.what();
  }
  TurnInput outside = shot(0.0, 3.0);
  outside.cue = Vec2{xb + 0.05, 0.1};
  EXPECT_THROW(m.play(outside), IllegalAction);
  ASSERT_TRUE(m.cuePlacementProblem({xb - 0.2, 0.25}));  // beyond the arc
  EXPECT_NE(m.cuePlacementProblem({xb - 0.2, 0.25})->find("in the D"), std::string::npos);
  TurnInput inside = shot(0.0, 3.0);
  inside.cue = Vec2{xb - 0.1, 0.1};
  const TurnRecord rec = m.play(inside);
  EXPECT_EQ(rec.verdict.shooter, Player::A);
  EXPECT_GT(rec.points_remaining, 0);
}

TEST(MatchSnooker, AColourPottedOnAFoulGoesBackOnItsSpot) {
  // Reds on; the black sent into the top-right pocket from a straight line: a foul (not on),
  // the black back on its spot, the opponent 7 points and the choice.
  Match m(snookerSetup(std::vector<BallState>{BallState::at(kCueBall, {1.40, 0.505}),
                                              BallState::at(1, {-1.0, -0.5}),
                                              BallState::at(21, {1.60, 0.705})}));
  const TurnRecord rec = m.play(shot(45.0, 2.5));
  ASSERT_EQ(rec.verdict.pocketed, std::vector<int>{21});
  EXPECT_EQ(rec.verdict.foul, rules::Foul::WrongBallFirst);
  EXPECT_EQ(rec.verdict.points[1], 7);
  const Vec2 spot = snooker::colourSpot(kTable, 21);
  EXPECT_EQ(where(m, 21).x, spot.x);
  EXPECT_EQ(where(m, 21).y, spot.y);
  EXPECT_TRUE(m.rack().awaitingDecision());
}

// A stroke that barely moves the cue ball away from the only red, hidden behind the pink.
std::vector<BallState> hiddenRed() {
  return {BallState::at(kCueBall, {0.0, 0.0}), BallState::at(1, {0.8, 0.0}),
          BallState::at(20, {0.3, 0.0})};
}

TEST(MatchSnooker, SnookeredAfterAFoulTheStrikerHasAFreeBall) {
  Match m(snookerSetup(hiddenRed()));
  const TurnRecord foul = m.play(shot(180.0, 0.1));
  EXPECT_EQ(foul.verdict.foul, rules::Foul::NoContact);
  EXPECT_FALSE(foul.verdict.miss);  // snookered before the stroke too
  EXPECT_TRUE(foul.free_ball_next);
  EXPECT_TRUE(rules::freeBall(m.rack()));
  m.play(decision(true));
  TurnInput free_ball = shot(0.0, 0.6);
  free_ball.call = rules::Call{20, PocketId::TopRight};
  const TurnRecord rec = m.play(free_ball);
  EXPECT_TRUE(rec.verdict.free_ball);
  EXPECT_EQ(rec.verdict.nominated, 20);
  EXPECT_TRUE(rec.verdict.legal());
}

TEST(MatchSnooker, NoFreeBallWhenABallOnIsInView) {
  std::vector<BallState> balls = hiddenRed();
  balls[2].pos = {0.3, 0.3};
  Match m(snookerSetup(balls));
  const TurnRecord foul = m.play(shot(180.0, 0.1));
  EXPECT_TRUE(foul.verdict.miss);
  EXPECT_FALSE(foul.free_ball_next);
  EXPECT_EQ(m.rack().pendingDecision(), rules::Decision::PlayPutBackOrReplace);
}

TEST(MatchSnooker, AfterAMissTheBallsAreReplacedAndTheOffenderPlaysAgain) {
  std::vector<BallState> balls = hiddenRed();
  balls[2].pos = {0.3, 0.3};
  Match m(snookerSetup(balls));
  m.play(shot(180.0, 0.3));
  EXPECT_LT(where(m, kCueBall).x, -0.01);
  const TurnRecord rec = m.play(decision(false, true));
  EXPECT_TRUE(rec.replace);
  EXPECT_EQ(rec.verdict.next, Player::A);
  EXPECT_EQ(where(m, kCueBall).x, 0.0);
  EXPECT_EQ(where(m, kCueBall).y, 0.0);
  EXPECT_EQ(m.rack().score(Player::B), 4);
  // Only a miss can be replaced.
  Match plain(snookerSetup(hiddenRed()));
  plain.play(shot(180.0, 0.1));
  EXPECT_THROW(plain.play(decision(false, true)), IllegalAction);
}

TEST(MatchSnooker, AfterAnInOffTheCueBallIsInHandInTheD) {
  // The cue ball straight into the top-right pocket.
  Match m(snookerSetup(std::vector<BallState>{BallState::at(kCueBall, {1.40, 0.505}),
                                              BallState::at(1, {-1.0, -0.5})}));
  const TurnRecord rec = m.play(shot(45.0, 2.5));
  EXPECT_EQ(rec.verdict.foul, rules::Foul::Scratch);
  m.play(decision(true));
  EXPECT_TRUE(m.cueMustBePlaced());
  TurnInput anywhere = shot(0.0, 1.0);
  anywhere.cue = Vec2{0.5, 0.0};
  EXPECT_THROW(m.play(anywhere), IllegalAction);
}

}  // namespace
}  // namespace nineball
