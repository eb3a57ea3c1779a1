// The rule interface carries what games beyond pool need: a score kept by the rack and a ball
// on that is not the lowest ball (snooker's colours, a carom point). A small book of this test's
// own plays by those rules through the same Rack the three pool games use.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "nineball/rules.hpp"

namespace nineball::rules {
namespace {

// Highest ball first; every ball potted scores its number; the rack ends when the table is
// empty, won by the player with more points.
class HighestFirstForPoints : public RuleBook {
 public:
  Game game() const override { return Game::NineBall; }
  RuleSet ruleSet() const override { return RuleSet::Wpa; }
  std::vector<int> legalFirstBalls(const RackState& s) const override {
    if (s.on_table.empty()) return {};
    return {*std::max_element(s.on_table.begin(), s.on_table.end())};
  }
  int ballOn(const RackState& s) const override {
    const auto balls = legalFirstBalls(s);
    return balls.empty() ? 0 : balls.front();
  }
  bool callRequired(const RackState&) const override { return false; }
  Verdict judge(RackState& s, const ShotSummary& shot, bool) const override {
    Verdict v;
    v.shooter = s.shooter;
    v.pocketed = shot.pocketed;
    const int seat = s.shooter == Player::A ? 0 : 1;
    for (int ball : shot.pocketed) {
      v.points[seat] += ball;
      s.on_table.erase(std::remove(s.on_table.begin(), s.on_table.end(), ball), s.on_table.end());
    }
    v.next = shot.pocketed.empty() ? other(s.shooter) : s.shooter;
    if (s.on_table.empty()) {
      const int a = s.score[0] + (seat == 0 ? v.points[0] : 0);
      const int b = s.score[1] + (seat == 1 ? v.points[1] : 0);
      v.winner = a >= b ? Player::A : Player::B;
    }
    return v;
  }
};

ShotSummary potting(std::vector<int> balls) {
  ShotSummary shot;
  shot.first_contact = balls.empty() ? std::nullopt : std::optional<int>(balls.front());
  shot.pocketed = std::move(balls);
  return shot;
}

TEST(RuleBooks, ABookSaysWhichBallIsOnWhenItIsNotTheLowest) {
  const HighestFirstForPoints book;
  Rack rack(book, {3, 1, 7}, false);
  EXPECT_EQ(rack.ballOn(), 7);
  EXPECT_EQ(rack.legalFirstBalls(), std::vector<int>{7});
  rack.shoot(potting({7}));
  EXPECT_EQ(rack.ballOn(), 3);
}

TEST(RuleBooks, TheRackKeepsTheScoreTheBookAwards) {
  const HighestFirstForPoints book;
  Rack rack(book, {1, 2, 5}, false);
  rack.shoot(potting({5}));
  EXPECT_EQ(rack.score(Player::A), 5);
  EXPECT_EQ(rack.score(Player::B), 0);
  EXPECT_EQ(rack.shooter(), Player::A);
  rack.shoot(potting({}));
  EXPECT_EQ(rack.shooter(), Player::B);
  rack.shoot(potting({2, 1}));
  EXPECT_EQ(rack.score(Player::A), 5);
  EXPECT_EQ(rack.score(Player::B), 3);
  ASSERT_TRUE(rack.over());
  EXPECT_EQ(rack.winner(), Player::A);
}

TEST(RuleBooks, PoolGamesKeepNoScoreAndTheLowestBallIsOn) {
  Rack rack(Game::NineBall, RuleSet::Wpa, {4, 2, 9}, false);
  EXPECT_EQ(rack.ballOn(), 2);
  ShotSummary shot = potting({2});
  shot.rail_after_contact = true;
  rack.shoot(shot);
  EXPECT_EQ(rack.score(Player::A), 0);
  EXPECT_EQ(rack.score(Player::B), 0);
  EXPECT_EQ(rack.ballOn(), 4);
}

}  // namespace
}  // namespace nineball::rules
