// A race's racks: who opens each, what each is racked from, and when the race is won.
#include "nineball/race.hpp"

#include <gtest/gtest.h>

namespace nineball {
namespace {

using rules::Player;

TEST(Race, AlternateBreaksGoAToBWhateverTheWinner) {
  EXPECT_EQ(rackOpener(BreakOrder::Alternate, 0, std::nullopt), Player::A);
  EXPECT_EQ(rackOpener(BreakOrder::Alternate, 1, Player::A), Player::B);
  EXPECT_EQ(rackOpener(BreakOrder::Alternate, 2, Player::B), Player::A);
  EXPECT_EQ(rackOpener(BreakOrder::Alternate, 3, Player::A), Player::B);
}

TEST(Race, WinnerBreaksGivesTheNextBreakToTheLastRacksWinner) {
  EXPECT_EQ(rackOpener(BreakOrder::Winner, 0, Player::B), Player::A);
  EXPECT_EQ(rackOpener(BreakOrder::Winner, 1, Player::B), Player::B);
  EXPECT_EQ(rackOpener(BreakOrder::Winner, 2, Player::A), Player::A);
}

TEST(Race, LaterRacksAreRackedAfreshFromTheNextSeed) {
  MatchSetup first;
  first.seed = 40;
  first.balls = std::vector<BallState>{};
  const MatchSetup same = rackSetup(first, 0, Player::A);
  EXPECT_TRUE(same.balls.has_value());
  EXPECT_EQ(same.seed, 40u);
  const MatchSetup third = rackSetup(first, 2, Player::B);
  EXPECT_FALSE(third.balls.has_value());
  EXPECT_EQ(third.seed, 42u);
  EXPECT_EQ(third.opener, Player::B);
}

TEST(Race, TheOpenerPlaysTheFirstStroke) {
  MatchSetup setup;
  setup.opener = Player::B;
  const Match match(setup);
  EXPECT_EQ(match.rack().shooter(), Player::B);
  EXPECT_TRUE(match.rack().isBreak());
  setup.setGame(rules::Game::ThreeCushion);
  EXPECT_THROW(Match{setup}, IllegalAction);
}

TEST(Race, TheRaceIsWonAtItsLength) {
  const Race race{3, BreakOrder::Alternate};
  RaceScore score;
  for (int i = 0; i < 2; ++i) score.count(Player::A);
  score.count(Player::B);
  score.count(std::nullopt);
  EXPECT_EQ(score.won[0], 2);
  EXPECT_EQ(score.won[1], 1);
  EXPECT_FALSE(score.winner(race));
  score.count(Player::A);
  EXPECT_EQ(score.winner(race), Player::A);
  EXPECT_FALSE(score.winner(Race{}));
  EXPECT_EQ(breakOrderFromName("winner"), BreakOrder::Winner);
  EXPECT_FALSE(breakOrderFromName("loser"));
}

}  // namespace
}  // namespace nineball
