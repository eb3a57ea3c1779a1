// A ball that leaves the table, in each rule book: always a foul; nine-ball and ten-ball leave
// jumped object balls off but spot the game ball, eight-ball spots them and loses the rack on
// the 8, snooker charges the ball forced off as one potted in the foul, three-cushion ends the
// inning and spots it; the cue ball off the table is in hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "nineball/rules.hpp"

namespace nineball::rules {
namespace {

bool holds(const std::vector<int>& balls, int b) {
  return std::find(balls.begin(), balls.end(), b) != balls.end();
}

std::vector<int> upTo(int last) {
  std::vector<int> balls;
  for (int b = 1; b <= last; ++b) balls.push_back(b);
  return balls;
}

// The ball on hit first, a rail after, `jumped` over a rail (0: the cue ball, then in hand as
// the physics' summary has it).
ShotSummary jumping(int first, std::vector<int> jumped) {
  ShotSummary s;
  s.first_contact = first;
  s.rail_after_contact = true;
  s.off_table = std::move(jumped);
  s.cue_pocketed = holds(s.off_table, 0);
  return s;
}

TEST(JumpedBall, NineBallLeavesAJumpedObjectBallOffButSpotsTheNine) {
  Rack r(Game::NineBall, RuleSet::Wpa, upTo(9), false);
  Verdict v = r.shoot(jumping(1, {5}));
  EXPECT_EQ(v.foul, Foul::JumpedBall);
  EXPECT_TRUE(v.ball_in_hand);
  EXPECT_EQ(v.next, Player::B);
  EXPECT_FALSE(holds(r.ballsOnTable(), 5));
  EXPECT_TRUE(v.to_spot.empty());
  v = r.shoot(jumping(1, {9}));
  EXPECT_EQ(v.foul, Foul::JumpedBall);
  EXPECT_EQ(v.to_spot, std::vector<int>{9});
  EXPECT_TRUE(holds(r.ballsOnTable(), 9));
  EXPECT_FALSE(v.winner.has_value());
}

TEST(JumpedBall, TenBallSpotsTheTen) {
  Rack r(Game::TenBall, RuleSet::Wpa, upTo(10), false);
  const Verdict v = r.shoot(jumping(1, {10, 4}));
  EXPECT_EQ(v.foul, Foul::JumpedBall);
  EXPECT_EQ(v.to_spot, std::vector<int>{10});
  EXPECT_FALSE(holds(r.ballsOnTable(), 4));
}

TEST(JumpedBall, TheCueBallOffTheTableIsInHand) {
  Rack r(Game::NineBall, RuleSet::Wpa, upTo(9), false);
  const Verdict v = r.shoot(jumping(1, {0}));
  EXPECT_EQ(v.foul, Foul::JumpedBall);
  EXPECT_TRUE(v.ball_in_hand);
}

TEST(JumpedBall, EightBallSpotsJumpedBallsAndTheEightOffLosesTheRack) {
  Rack r(Game::EightBall, RuleSet::Wpa, upTo(15), false);
  Verdict v = r.shoot(jumping(1, {12}));
  EXPECT_EQ(v.foul, Foul::JumpedBall);
  EXPECT_EQ(v.to_spot, std::vector<int>{12});
  EXPECT_TRUE(holds(r.ballsOnTable(), 12));
  EXPECT_TRUE(v.ball_in_hand);
  Rack eight(Game::EightBall, RuleSet::Wpa, upTo(15), false);
  v = eight.shoot(jumping(1, {8}));
  ASSERT_TRUE(v.winner.has_value());
  EXPECT_EQ(*v.winner, Player::B);
}

TEST(JumpedBall, SnookerChargesABallForcedOffAsOnePottedInTheFoul) {
  constexpr int kPink = 20, kBlack = 21;
  std::vector<int> balls = upTo(15);
  for (int c = 16; c <= kBlack; ++c) balls.push_back(c);
  Rack r(Game::Snooker, RuleSet::Wpbsa, balls, false);
  // A red hit, the black forced off: seven away, and the black back on its spot.
  Verdict v = r.shoot(jumping(3, {kBlack}));
  EXPECT_EQ(v.foul, Foul::JumpedBall);
  EXPECT_EQ(v.points[1], 7);
  EXPECT_TRUE(holds(v.to_spot, kBlack));
  // A red forced off stays off; the penalty is the least, four.
  Rack again(Game::Snooker, RuleSet::Wpbsa, balls, false);
  v = again.shoot(jumping(3, {5}));
  EXPECT_EQ(v.points[1], 4);
  EXPECT_FALSE(holds(again.ballsOnTable(), 5));
  EXPECT_FALSE(holds(v.to_spot, 5));
  (void)kPink;
}

TEST(JumpedBall, ThreeCushionEndsTheInningWithoutAPointAndSpotsTheBall) {
  constexpr int kYellow = 1, kRed = 2;
  Rack r(Game::ThreeCushion, RuleSet::Umb, {kYellow, kRed});
  ShotSummary s;
  s.first_contact = kRed;
  s.cue_touches = {kRed, kYellow};
  s.cue_cushions = 3;
  s.cue_cushions_before = {0, 3};
  s.off_table = {kRed};
  const Verdict v = r.shoot(s);
  EXPECT_EQ(v.foul, Foul::JumpedBall);
  EXPECT_EQ(v.points[0], 0);
  EXPECT_EQ(v.next, Player::B);
  EXPECT_EQ(v.to_spot, std::vector<int>{kRed});
}

}  // namespace
}  // namespace nineball::rules
