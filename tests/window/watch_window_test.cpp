// A rack watched again (--watch): under Xvfb the script's turns are played on screen one after
// another, and once they are over the table is the one the script leaves when played at once.
#include <gtest/gtest.h>
#include <unistd.h>

#include <SFML/Graphics/Image.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "support/picture_diff.hpp"
#include "support/xvfb_run.hpp"

namespace nineball::window {
namespace {

using nineball::testing::kSmallHeight;
using nineball::testing::kSmallWidth;

sf::Image shoot(const std::string& stem, const std::string& args) {
  const std::string png = stem + ".png";
  const testing::XvfbRun run =
      testing::runGameUnderXvfb(args + " --screenshot '" + png + "'", kSmallWidth, kSmallHeight);
  EXPECT_EQ(run.status, 0) << run.err;
  sf::Image image;
  EXPECT_TRUE(image.loadFromFile(png)) << run.err;
  std::remove(png.c_str());
  return image;
}

TEST(WatchWindow, TheScriptsTurnsPlayOnScreenAndEndWhereTheScriptEnds) {
  ASSERT_TRUE(testing::haveXvfbRun())
      << "xvfb-run not found: install xvfb and xauth (bash scripts/setup.sh)";
  const std::string stem = "/tmp/nineball-test-watch-" + std::to_string(getpid());
  {
    std::ofstream out(stem + ".json");
    out << R"({"seed": 3, "turns": [{"heading_deg": 0, "speed": 10, "cue": [-0.635, 0.0]},
                                    {"heading_deg": 30, "speed": 2}]})";
  }
  const std::string script = "--script '" + stem + ".json'";
  // Forty simulated seconds: both turns played and at rest.
  const sf::Image watched = shoot(stem + "-watched", script + " --watch --frames 2400");
  const sf::Image at_once = shoot(stem + "-at-once", script);
  const sf::Image first = shoot(stem + "-first", script + " --watch --frames 2");
  std::remove((stem + ".json").c_str());
  // The balls where the script leaves them (the numbers turned as they rolled, and the gauge at
  // the last turn's power, differ a little).
  EXPECT_LT(nineball::testing::differingShare(watched, at_once), 0.01);
  // Two frames in, nothing is played yet: the rack.
  EXPECT_GT(nineball::testing::differingShare(first, at_once), 0.02);
}

}  // namespace
}  // namespace nineball::window
