// Two game windows on this machine play one rack over loopback (issue 35): each takes its own
// seat's turns from its script, the other seat's come over the network, and both pictures
// show the same table.
#include <gtest/gtest.h>
#include <unistd.h>

#include <SFML/Graphics/Image.hpp>
#include <SFML/Network/TcpListener.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <future>
#include <string>
#include <thread>

#include "net/free_port.hpp"
#include "nineball/colours.hpp"
#include "support/xvfb_run.hpp"

namespace {

using nineball::testing::freePort;

using nineball::testing::kHeight;
using nineball::testing::kWidth;
// The table and its rails in a 1280x800 window (the HUD's bands above and below it differ:
// each window names its own opponent).
constexpr unsigned kTableTop = 90, kTableBottom = 712, kTableLeft = 56, kTableRight = 1224;

using nineball::testing::haveXvfbRun;
using nineball::testing::runGameUnderXvfb;
using nineball::testing::XvfbRun;

std::string tempPath(const std::string& name) {
  return "/tmp/nineball-online-" + std::to_string(getpid()) + "-" + name;
}

void write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

// Pixels of the table region whose colour differs between the two pictures.
long tableDifference(const sf::Image& a, const sf::Image& b) {
  long differ = 0;
  for (unsigned y = kTableTop; y < kTableBottom; ++y) {
    for (unsigned x = kTableLeft; x < kTableRight; ++x) {
      if (a.getPixel(x, y) != b.getPixel(x, y)) ++differ;
    }
  }
  return differ;
}

// The cloth's colour (nineball/colours.hpp), within the tolerance of the other screenshot tests.
bool clothLike(sf::Color c) {
  const nineball::Rgb cloth = nineball::kCloth;
  return std::abs(c.r - cloth.r) <= 24 && std::abs(c.g - cloth.g) <= 24 &&
         std::abs(c.b - cloth.b) <= 24;
}

// Pixels of the table region that are cloth in one picture and not in the other: where the
// balls (and their shadows) lie. Unlike tableDifference it does not see which way each ball's
// number faces, which a rack replayed at once (a rejoin) does not turn as one played on screen.
long ballPlacesDifference(const sf::Image& a, const sf::Image& b) {
  long differ = 0;
  for (unsigned y = kTableTop; y < kTableBottom; ++y) {
    for (unsigned x = kTableLeft; x < kTableRight; ++x) {
      if (clothLike(a.getPixel(x, y)) != clothLike(b.getPixel(x, y))) ++differ;
    }
  }
  return differ;
}

// The nine-ball rack of seed 3: the host (A) breaks and pots the 6, misses; the joiner (B)
// fouls; A fouls; B fouls. Then it is A's move with its script over: the rack ends there.
// (The turns of `nineball match` on the same five turns: A, A, B, A, B.)
constexpr const char* kHostScript =
    R"({"game": "nine-ball", "rules": "wpa", "seed": 3, "turns": [
         {"heading_deg": 0.4, "speed": 9}, {"heading_deg": 10, "speed": 3},
         {"heading_deg": 95, "speed": 4}]})";
constexpr const char* kJoinScript =
    R"({"game": "nine-ball", "rules": "wpa", "seed": 3, "turns": [
         {"heading_deg": 200, "speed": 2.5}, {"heading_deg": -30, "speed": 3}]})";

TEST(OnlineWindow, TwoWindowsPlayOneRackAndShowTheSameTable) {
  ASSERT_TRUE(haveXvfbRun())
      << "xvfb-run not found: the online window tests need a virtual display";
  const unsigned short port = freePort();
  ASSERT_NE(port, 0);
  const std::string host_script = tempPath("host.json"), join_script = tempPath("join.json");
  const std::string host_png = tempPath("host.png"), join_png = tempPath("join.png");
  const std::string alone_png = tempPath("alone.png"), alone_script = tempPath("alone.json");
  write(host_script, kHostScript);
  write(join_script, kJoinScript);
  write(alone_script, R"({"game": "nine-ball", "rules": "wpa", "seed": 3, "turns": []})");
  std::remove(host_png.c_str());
  std::remove(join_png.c_str());

  auto host = std::async(std::launch::async, [&] {
    return runGameUnderXvfb("--host " + std::to_string(port) +
                                " --code TEST-CODE --name Ann --script '" + host_script +
                                "' --screenshot '" + host_png + "'",
                            kWidth, kHeight);
  });
  // The host's display and port first; the joiner retries anyway while nobody answers.
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  const XvfbRun join = runGameUnderXvfb("--join 127.0.0.1:" + std::to_string(port) +
                                            " --code TEST-CODE --name Bob --script '" +
                                            join_script + "' --screenshot '" + join_png + "'",
                                        kWidth, kHeight);
  const XvfbRun hosted = host.get();
  ASSERT_EQ(join.status, 0) << join.err;
  ASSERT_EQ(hosted.status, 0) << hosted.err;

  sf::Image host_image, join_image, alone_image;
  ASSERT_TRUE(host_image.loadFromFile(host_png));
  ASSERT_TRUE(join_image.loadFromFile(join_png));
  ASSERT_EQ(host_image.getSize(), sf::Vector2u(kWidth, kHeight));
  ASSERT_EQ(join_image.getSize(), sf::Vector2u(kWidth, kHeight));
  // The same balls in the same places: the table regions are identical, pixel for pixel.
  EXPECT_EQ(tableDifference(host_image, join_image), 0);

  // And the rack was played: the table is not the opening rack any more.
  const XvfbRun alone = runGameUnderXvfb(
      "--script '" + alone_script + "' --screenshot '" + alone_png + "'", kWidth, kHeight);
  ASSERT_EQ(alone.status, 0) << alone.err;
  ASSERT_TRUE(alone_image.loadFromFile(alone_png));
  EXPECT_GT(tableDifference(host_image, alone_image), 2000);
  EXPECT_GT(ballPlacesDifference(host_image, alone_image), 2000);

  for (const std::string& f :
       {host_script, join_script, alone_script, host_png, join_png, alone_png}) {
    std::remove(f.c_str());
  }
}

// The first joiner is killed in the middle of the rack; a second one (the same player started
// again) rejoins, replays the turns so far from the host's welcome, and the rack goes on.
TEST(OnlineWindow, AJoinerKilledMidRackRejoinsAndTheRackEndsInStep) {
  ASSERT_TRUE(haveXvfbRun())
      << "xvfb-run not found: the online window tests need a virtual display";
  const unsigned short port = freePort();
  ASSERT_NE(port, 0);
  const std::string host_script = tempPath("rhost.json"), join_script = tempPath("rjoin.json");
  const std::string host_png = tempPath("rhost.png"), join_png = tempPath("rjoin.png");
  write(host_script, kHostScript);
  write(join_script, kJoinScript);
  const std::string join_args = "--join 127.0.0.1:" + std::to_string(port) +
                                " --code TEST-CODE --name Bob --script '" + join_script +
                                "' --screenshot '" + join_png + "'";

  auto host = std::async(std::launch::async, [&] {
    return runGameUnderXvfb("--host " + std::to_string(port) +
                                " --code TEST-CODE --name Ann --script '" + host_script +
                                "' --screenshot '" + host_png + "'",
                            kWidth, kHeight);
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  // Killed as a crash or a pulled plug would: no goodbye.
  const std::string killed = "xvfb-run -a -n " + std::to_string(100 + getpid() % 90) +
                             " -s '-screen 0 1280x800x24' timeout -s KILL 5 '" + NINEBALL_BINARY +
                             "' --mute --size 1280x800 " + join_args + " >/dev/null 2>&1";
  EXPECT_NE(std::system(killed.c_str()), 0);
  const XvfbRun rejoin = runGameUnderXvfb("--log-level info " + join_args, kWidth, kHeight);
  const XvfbRun hosted = host.get();
  ASSERT_EQ(rejoin.status, 0) << rejoin.err;
  ASSERT_EQ(hosted.status, 0) << hosted.err;
  EXPECT_NE(hosted.err.find("link lost"), std::string::npos) << hosted.err;
  // The rejoiner found turns already played in the welcome.
  const auto joined = rejoin.err.find("joined Ann: ");
  ASSERT_NE(joined, std::string::npos) << rejoin.err;
  EXPECT_NE(rejoin.err[joined + 12], '0') << rejoin.err;

  sf::Image host_image, join_image;
  ASSERT_TRUE(host_image.loadFromFile(host_png));
  ASSERT_TRUE(join_image.loadFromFile(join_png));
  // Every ball in the same place (a ball 1 px off would differ along its whole rim, ~70 px).
  EXPECT_LE(ballPlacesDifference(host_image, join_image), 10);
  for (const std::string& f : {host_script, join_script, host_png, join_png}) {
    std::remove(f.c_str());
  }
}

TEST(OnlineWindow, AJoinerNobodyAnswersFailsWithAMessage) {
  ASSERT_TRUE(haveXvfbRun())
      << "xvfb-run not found: the online window tests need a virtual display";
  const unsigned short port = freePort();
  ASSERT_NE(port, 0);
  const std::string script = tempPath("lonely.json"), png = tempPath("lonely.png");
  write(script, kJoinScript);
  const XvfbRun r =
      runGameUnderXvfb("--join 127.0.0.1:" + std::to_string(port) + " --code TEST-CODE --script '" +
                           script + "' --screenshot '" + png + "'",
                       kWidth, kHeight, "NINEBALL_ONLINE_WAIT=3");
  EXPECT_NE(r.status, 0);  // 1 (xvfb-run may say 5 when its own clean-up fails)
  EXPECT_NE(r.err.find("No host answered at 127.0.0.1:" + std::to_string(port)), std::string::npos)
      << r.err;
  std::remove(script.c_str());
  std::remove(png.c_str());
}

}  // namespace
