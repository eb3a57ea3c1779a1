// New racks: a person's games without --seed draw a new seed each, so that no two start with the
// same rack; --seed, screenshots, --frames and scripts keep theirs, run after run.
#include "window/rack_seed.hpp"

#include <gtest/gtest.h>

#include <set>

#include "window/game_rolling.hpp"
#include "window/game_session.hpp"

namespace nineball::window {
namespace {

std::vector<BallState> rackOf(std::uint64_t seed) {
  MatchSetup setup;
  setup.seed = seed;
  return GameSession(setup).match().balls();
}

bool sameBalls(const std::vector<BallState>& a, const std::vector<BallState>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].id != b[i].id || !(a[i].pos == b[i].pos)) return false;
  }
  return true;
}

TEST(RackSeed, EachDrawIsNewAndGivesANewRack) {
  std::set<std::uint64_t> seeds;
  for (int i = 0; i < 8; ++i) seeds.insert(freshSeed());
  EXPECT_EQ(seeds.size(), 8u);
  // Of eight games started in a row, the racks are not all one (nine-ball shuffles the 2-8).
  int differing = 0;
  const std::vector<BallState> first = rackOf(*seeds.begin());
  for (std::uint64_t s : seeds) differing += sameBalls(rackOf(s), first) ? 0 : 1;
  EXPECT_GE(differing, 6);
}

TEST(RackSeed, OnlyAPersonsGameWithoutSeedDrawsOne) {
  app::GameOptions person;
  EXPECT_TRUE(drawsFreshSeeds(person));
  app::GameOptions seeded;
  seeded.seed_given = true;
  EXPECT_FALSE(drawsFreshSeeds(seeded));
  app::GameOptions picture;
  picture.screenshot = "a.png";
  EXPECT_FALSE(drawsFreshSeeds(picture));
  app::GameOptions frames;
  frames.frames = 10;
  EXPECT_FALSE(drawsFreshSeeds(frames));
  app::GameOptions script;
  script.script = "match.json";
  EXPECT_FALSE(drawsFreshSeeds(script));
  app::GameOptions joiner;
  joiner.join = "host:4000";
  EXPECT_FALSE(drawsFreshSeeds(joiner));
}

TEST(RackSeed, TheSameSeedPlaysTheSameRacksAgain) {
  // The seed the log shows and the save keeps gives the game's racks again, the rematches too.
  MatchSetup setup;
  setup.seed = 0x5EEDull;
  GameSession a(setup), b(setup);
  EXPECT_TRUE(sameBalls(a.match().balls(), b.match().balls()));
  for (GameSession* s : {&a, &b}) {
    ASSERT_TRUE(s->shoot());
    ASSERT_TRUE(roll(*s));
  }
  EXPECT_TRUE(sameBalls(a.match().balls(), b.match().balls()));
}

}  // namespace
}  // namespace nineball::window
