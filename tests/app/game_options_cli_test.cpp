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

TEST(GameOptionsCli, HostTakesAnOptionalPortAndJoinAnAddress) {
  EXPECT_FALSE(parse({}).host_port.has_value());
  EXPECT_EQ(parse({"--host"}).host_port, std::optional<unsigned short>(47047));
  EXPECT_EQ(parse({"--host", "5000"}).host_port, std::optional<unsigned short>(5000));
  EXPECT_EQ(parse({"--join", "192.168.1.20:5000"}).join, "192.168.1.20:5000");
  EXPECT_EQ(parse({"--join", "friend.example"}).join, "friend.example");
  EXPECT_EQ(parse({"--name", "Ann"}).name, "Ann");
}

TEST(GameOptionsCli, BadPortsAddressesAndHostWithJoinAreRefused) {
  EXPECT_THROW(parse({"--host", "0"}), CLI::ValidationError);
  EXPECT_THROW(parse({"--host", "65536"}), CLI::ValidationError);
  EXPECT_THROW(parse({"--host", "port"}), CLI::ValidationError);
  EXPECT_THROW(parse({"--join", ":47047"}), CLI::ValidationError);
  EXPECT_THROW(parse({"--join", "host:99999"}), CLI::ValidationError);
  EXPECT_THROW(parse({"--host", "--join", "host"}), CLI::ExcludesError);
  EXPECT_THROW(parse({"--name", ""}), CLI::ValidationError);
}

TEST(GameOptionsCli, SeedGivenIsKnownAndWatchNeedsAScript) {
  EXPECT_FALSE(parse({}).seed_given);
  EXPECT_TRUE(parse({"--seed", "1"}).seed_given);
  EXPECT_TRUE(parse({"--script", "rack.json", "--watch"}).watch);
  EXPECT_THROW(parse({"--watch"}), CLI::RequiresError);
}

}  // namespace
}  // namespace nineball::app
