// The game window's options: which of them the command line gave, defaults included.
#include "app/game_options_cli.hpp"

#include <gtest/gtest.h>

namespace nineball::app {
namespace {

GameOptions parse(std::vector<std::string> args) {
  CLI::App app;
  GameOptions o;
  addGameOptions(app, o);
  std::reverse(args.begin(), args.end());  // CLI11 takes them last first
  app.parse(args);
  return o;
}

TEST(GameOptionsCli, AnOptionGivenIsKnownAsGivenEvenAtItsDefault) {
  const GameOptions none = parse({});
  EXPECT_FALSE(none.game_given);
  EXPECT_FALSE(none.rules_given);
  EXPECT_FALSE(none.opponent_given);
  const GameOptions o = parse({"--game", "nine-ball", "--opponent", "human", "--rules", "wpa"});
  EXPECT_TRUE(o.game_given);
  EXPECT_TRUE(o.rules_given);
  EXPECT_TRUE(o.opponent_given);
  EXPECT_EQ(o.opponent, "human");
}

}  // namespace
}  // namespace nineball::app
