// Three-cushion played through the real physics: the UMB opening position on a carom table with
// carom balls, each player striking their own ball, frozen balls set up again.
#include <gtest/gtest.h>

#include <cmath>

#include "nineball/carom_rack.hpp"
#include "nineball/match.hpp"
#include "play/match_turns.hpp"

namespace nineball {
namespace {

using play_test::shot;
using play_test::where;
using rules::Game;
using rules::Player;

constexpr int kWhite = 0;
constexpr int kYellow = 1;
constexpr int kRed = 2;

MatchSetup threeCushion(std::uint64_t seed = 1) {
  MatchSetup s;
  s.setGame(Game::ThreeCushion);
  s.seed = seed;
  return s;
}

TEST(MatchThreeCushion, StartsFromTheUmbOpeningPositionWithCaromEquipment) {
  const Match m(threeCushion());
  EXPECT_FALSE(m.world().table().def.pockets);
  EXPECT_EQ(m.world().table().def.length, 2.84);
  EXPECT_EQ(m.world().physics().ball_radius, PhysicsParams::carom().ball_radius);
  EXPECT_EQ(m.rack().targetPoints(), 25);
  EXPECT_EQ(m.balls().size(), 3u);
  // Red on the top spot, yellow on the bottom spot, white 182 mm beside it on the starting line.
  EXPECT_EQ(where(m, kRed).x, 0.71);
  EXPECT_EQ(where(m, kYellow).x, -0.71);
  EXPECT_EQ(where(m, kYellow).y, 0.0);
  EXPECT_EQ(where(m, kWhite).x, -0.71);
  EXPECT_NEAR(std::abs(where(m, kWhite).y), 0.182, 1e-12);
  EXPECT_NE(where(Match(threeCushion(2)), kWhite).y, where(m, kWhite).y);  // the other side
  EXPECT_FALSE(m.cueInHand());
  EXPECT_EQ(m.rack().cueBall(), kWhite);
}

TEST(MatchThreeCushion, EachPlayerStrikesTheirOwnBall) {
  Match m(threeCushion());
  // A misses on purpose: a soft shot away from both balls.
  const TurnRecord a = m.play(shot(180.0, 0.5));
  EXPECT_EQ(a.verdict.next, Player::B);
  EXPECT_EQ(a.score.a.innings, 1);
  const Vec2 white = where(m, kWhite);
  const Vec2 yellow = where(m, kYellow);
  EXPECT_EQ(m.rack().cueBall(), kYellow);
  m.play(shot(-90.0, 0.4));  // B's yellow rolls towards the bottom cushion, alone
  EXPECT_EQ(where(m, kWhite).x, white.x);
  EXPECT_LT(where(m, kYellow).y, yellow.y - 0.05);
  EXPECT_EQ(rules::innings(m.rack(), Player::B), 1);
}

TEST(MatchThreeCushion, FrozenBallsAreSetUpAgainAndPlayedAsAnOpening) {
  MatchSetup s = threeCushion();
  const double r = s.physics.ball_radius;
  // B's yellow rests against the red; A's shot goes nowhere near them.
  s.balls = {BallState::at(kWhite, {-1.0, -0.5}), BallState::at(kRed, {0.5, 0.3}),
             BallState::at(kYellow, {0.5 + 2.0 * r + 1e-7, 0.3})};
  Match m(s);
  EXPECT_FALSE(m.rack().isBreak());
  m.play(shot(180.0, 0.3));
  EXPECT_EQ(m.rack().shooter(), Player::B);
  // The opening position, B's ball on the starting spot and A's on the bottom spot.
  EXPECT_EQ(where(m, kRed).x, 0.71);
  EXPECT_EQ(where(m, kWhite).x, -0.71);
  EXPECT_EQ(where(m, kWhite).y, 0.0);
  EXPECT_NEAR(std::abs(where(m, kYellow).y), 0.182, 1e-12);
  EXPECT_TRUE(m.rack().isBreak());
  EXPECT_EQ(m.rack().legalFirstBalls(), (std::vector<int>{kRed}));
}

}  // namespace
}  // namespace nineball
