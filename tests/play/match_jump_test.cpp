// Jumps in a match: a jump shot is a legal stroke; a stroke that sends the cue ball over a rail
// is the rule book's foul, the next player has it in hand and places it, and the ball is back
// on the table; an object ball jumped in eight-ball is spotted.
#include <gtest/gtest.h>

#include <algorithm>

#include "nineball/match.hpp"

namespace nineball {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

TurnInput stroke(double heading_deg, double speed, double elevation_deg) {
  TurnInput t;
  t.shot = Shot::withSpeed(heading_deg, speed);
  t.shot.elevation_rad = elevation_deg * kDeg;
  return t;
}

MatchSetup layout(rules::Game game, std::vector<BallState> balls) {
  MatchSetup s;
  s.setGame(game);
  s.balls = std::move(balls);
  return s;
}

TEST(MatchJump, TheCueBallOverARailIsAFoulAndInHandForTheNextPlayer) {
  // The 1 far away on the left; the cue ball driven hard at the top rail, 45 deg up.
  Match m(
      layout(rules::Game::NineBall, {BallState::at(0, {0.3, 0.3}), BallState::at(1, {-0.9, 0.0}),
                                     BallState::at(9, {-0.9, 0.3})}));
  const TurnRecord r = m.play(stroke(90.0, 8.0, 45.0));
  EXPECT_EQ(r.verdict.foul, rules::Foul::JumpedBall);
  EXPECT_TRUE(m.cueInHand());
  const BallState cue = m.balls().front();
  EXPECT_TRUE(cue.off_table);
  // The next player places it and plays on.
  TurnInput next = stroke(180.0, 2.0, 0.0);
  next.cue = Vec2{0.0, 0.0};
  const TurnRecord r2 = m.play(next);
  EXPECT_FALSE(m.balls().front().off_table);
  EXPECT_EQ(r2.shooter, rules::Player::B);
}

TEST(MatchJump, AJumpShotThatHitsTheBallOnIsLegal) {
  // The 1 straight ahead, 0.8 m on, nothing between: a jump onto it is a fair stroke.
  Match m(layout(
      rules::Game::NineBall,
      {BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.2, 0.0}), BallState::at(9, {0.9, 0.5})}));
  const TurnRecord r = m.play(stroke(0.0, 4.0, 30.0));
  EXPECT_EQ(r.verdict.foul, rules::Foul::None) << rules::foulName(r.verdict.foul);
}

}  // namespace
}  // namespace nineball
