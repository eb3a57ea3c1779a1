// The game picked in the start menu is drawn on its own table: under Xvfb, the window started
// as one game, the menu's Game row turned to another and Play chosen, gives the same picture as
// the other game started from the command line (the table, its pockets and marks, the balls).
#include <gtest/gtest.h>
#include <unistd.h>

#include <SFML/Graphics/Image.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/picture_diff.hpp"
#include "support/xvfb_run.hpp"

namespace nineball::window {
namespace {

using nineball::testing::kSmallHeight;
using nineball::testing::kSmallWidth;

// The games in the menu's order (the registry's), the Game row's Right presses away from
// nine-ball.
const char* const kGames[] = {"nine-ball", "eight-ball", "ten-ball", "three-cushion", "snooker"};

class MenuTableWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(testing::haveXvfbRun())
        << "xvfb-run not found: install xvfb and xauth (bash scripts/setup.sh)";
    dir_ = std::filesystem::temp_directory_path() /
           ("nineball-menu-table-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // The picture after `args`, with a settings folder of this test's own (no remembered choice,
  // no saved rack) and `keys` typed into the start menu when given.
  sf::Image shoot(const std::string& name, const std::string& args, const std::string& keys) {
    const std::string png = (dir_ / (name + ".png")).string();
    std::string env = "XDG_CONFIG_HOME='" + (dir_ / "config").string() + "' XDG_STATE_HOME='" +
                      (dir_ / "state").string() + "'";
    if (!keys.empty()) env += " NINEBALL_MENU_KEYS='" + keys + "'";
    const testing::XvfbRun run = testing::runGameUnderXvfb(args + " --screenshot '" + png + "'",
                                                           kSmallWidth, kSmallHeight, env);
    sf::Image image;
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_TRUE(image.loadFromFile(png)) << name << ": " << run.err;
    return image;
  }

  std::filesystem::path dir_;
};

// The menu's keys that turn the Game row `steps` to the right and play (two players, so the
// computer's level row is skipped: Play, Practice, Opponent, Game).
std::string pickGame(int steps) {
  std::string keys = "down,down,down";
  for (int i = 0; i < steps; ++i) keys += ",right";
  return keys + ",up,up,up,enter";
}

TEST_F(MenuTableWindow, EachGamePickedInTheMenuIsDrawnOnItsOwnTable) {
  const std::string common = "--opponent human --seed 5";
  for (int g = 1; g < 5; ++g) {
    SCOPED_TRACE(kGames[g]);
    const sf::Image picked =
        shoot(std::string("menu-") + kGames[g], "--menu --game nine-ball " + common, pickGame(g));
    const sf::Image direct = shoot(std::string("direct-") + kGames[g],
                                   "--game " + std::string(kGames[g]) + " " + common, "");
    // The start menu's own picture is not the game: the keys did pick and play.
    EXPECT_LT(nineball::testing::differingShare(picked, direct), 0.002);
  }
}

TEST_F(MenuTableWindow, APoolGamePickedAfterSnookerIsDrawnOnThePoolTable) {
  const std::string common = "--opponent human --seed 5";
  // From snooker (the last game) one step to the right is nine-ball, one more eight-ball.
  const sf::Image picked = shoot("menu-eight", "--menu --game snooker " + common, pickGame(2));
  const sf::Image direct = shoot("direct-eight", "--game eight-ball " + common, "");
  EXPECT_LT(nineball::testing::differingShare(picked, direct), 0.002);
}

TEST_F(MenuTableWindow, SnookerPickedInTheMenuBreaksOffOnTheSnookerTable) {
  // The break-off played for a few frames: the balls roll on the table the physics has.
  const std::string common = "--opponent human --seed 5 --frames 90";
  const sf::Image picked = shoot("menu-break", "--menu --game nine-ball " + common, pickGame(4));
  const sf::Image direct = shoot("direct-break", "--game snooker " + common, "");
  EXPECT_LT(nineball::testing::differingShare(picked, direct), 0.002);
}

TEST_F(MenuTableWindow, KeysThatPickNothingEndTheRunWithoutHanging) {
  const std::string png = (dir_ / "none.png").string();
  const std::string env = "XDG_CONFIG_HOME='" + (dir_ / "config").string() + "' XDG_STATE_HOME='" +
                          (dir_ / "state").string() + "'";
  const testing::XvfbRun bad =
      testing::runGameUnderXvfb("--menu --screenshot '" + png + "'", kSmallWidth, kSmallHeight,
                                env + " NINEBALL_MENU_KEYS=down,jump");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.err.find("\"jump\" is not a menu key"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace nineball::window
