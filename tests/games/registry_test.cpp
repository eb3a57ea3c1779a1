// The game registry: every game is data the rest of the program reads (its name, balls, rule
// sets, rack, ball set and tables), so the checks here hold for any game added to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>
#include <string>

#include "games/game_texts.hpp"
#include "nineball/games.hpp"
#include "nineball/params.hpp"

namespace nineball {
namespace {

TEST(GameRegistry, NamesAreUniqueAndEachIsFoundByItsName) {
  std::set<std::string> seen;
  for (const GameDef& g : allGames()) {
    EXPECT_TRUE(seen.insert(g.name).second) << g.name;
    ASSERT_NE(gameNamed(g.name), nullptr) << g.name;
    EXPECT_EQ(gameNamed(g.name)->id, g.id) << g.name;
    EXPECT_EQ(&gameDef(g.id), gameNamed(g.name)) << g.name;
  }
  EXPECT_EQ(gameNamed("snooker-on-ice"), nullptr);
  EXPECT_EQ(&defaultGame(), &allGames().front());
}

TEST(GameRegistry, EveryGameHasItsOwnTextsAndAPointsGameOffersItsDistance) {
  for (const GameDef& g : allGames()) {
    const GameTexts& t = gameTexts(g.id);
    EXPECT_FALSE(t.help.empty()) << g.name;
    EXPECT_NE(std::string(t.made), "") << g.name;
    // The menu offers a distance exactly for a game played to points, its default among them.
    EXPECT_EQ(t.points_choices.empty(), g.default_points == 0) << g.name;
    if (g.default_points > 0) {
      EXPECT_EQ(std::count(t.points_choices.begin(), t.points_choices.end(), g.default_points), 1)
          << g.name;
    }
    // A game's texts are its own: no two games share a help screen.
    for (const GameDef& other : allGames()) {
      if (other.id != g.id) {
        EXPECT_NE(gameTexts(other.id).help, t.help) << g.name;
      }
    }
  }
}

TEST(GameRegistry, EveryGameRacksItsOwnBallsOnEachOfItsTables) {
  for (const GameDef& g : allGames()) {
    ASSERT_NE(g.rack, nullptr) << g.name;
    ASSERT_FALSE(g.tables.empty()) << g.name;
    ASSERT_FALSE(g.rule_sets.empty()) << g.name;
    for (const std::string& name : g.tables) {
      const auto table = TableDef::named(name);
      ASSERT_TRUE(table) << g.name << ": " << name;
      std::set<int> racked;
      for (const BallState& b : g.rack(*table, 0.028575, 1, 0.0)) racked.insert(b.id);
      std::set<int> expected(g.balls.begin(), g.balls.end());
      // A game that never puts the cue ball in hand places it in its opening position.
      if (!g.cue_in_hand) expected.insert(kCueBall);
      EXPECT_EQ(racked, expected) << g.name << " " << name;
    }
  }
}

// MatchSetup::setGame takes the game's first table and its preset by name: each must exist.
TEST(GameRegistry, EveryGamesEquipmentIsBuiltIn) {
  for (const GameDef& g : allGames()) {
    EXPECT_TRUE(PhysicsParams::preset(g.physics)) << g.name << ": " << g.physics;
    for (const std::string& name : g.tables)
      EXPECT_TRUE(TableDef::named(name)) << g.name << ": " << name;
  }
}

TEST(GameRegistry, EveryBallOfAGameHasALookAndPoolBallsShowTheirNumbers) {
  for (const GameDef& g : allGames()) {
    ASSERT_NE(g.looks, nullptr) << g.name;
    EXPECT_FALSE(g.looks(kCueBall).numbered) << g.name;
    // Pool's object balls carry numbers; carom's three are told apart by colour alone.
    const bool numbered = g.looks == &poolBallLook;
    std::set<int> colours;
    for (int id : g.balls) {
      const BallLook look = g.looks(id);
      EXPECT_EQ(look.numbered, numbered) << g.name << " ball " << id;
      colours.insert(look.colour.r << 16 | look.colour.g << 8 | look.colour.b);
    }
    // Pool sets repeat a colour on a solid and its stripe only: 8 colours for 15 balls; snooker
    // has 7 for 21 (the reds alike).
    EXPECT_GE(colours.size(), std::min<std::size_t>(g.balls.size(), 7)) << g.name;
  }
}

}  // namespace
}  // namespace nineball
