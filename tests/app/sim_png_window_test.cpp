// nineball sim --png: the shot drawn by the game's renderer under Xvfb, checked pixel by pixel.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <SFML/Graphics/Image.hpp>
#include <cmath>
#include <cstdlib>
#include <variant>

#include "app/cli_runner.hpp"
#include "io/scene_json.hpp"
#include "nineball/colours.hpp"
#include "nineball/sim.hpp"
#include "render/ball_spin.hpp"
#include "render/view_transform.hpp"
#include "support/xvfb_run.hpp"

namespace nineball::testing {
namespace {

// There is no antialiasing: a path's or a ball's pixels are its colour within this much.
constexpr int kTolerance = 30;

bool near(sf::Color c, Rgb want) {
  return std::abs(c.r - want.r) <= kTolerance && std::abs(c.g - want.g) <= kTolerance &&
         std::abs(c.b - want.b) <= kTolerance;
}

const char* const kScene =
    R"({"balls": [{"id": 0, "x": -0.6, "y": 0.0}, {"id": 3, "x": 0.3, "y": 0.0}],
        "shot": {"heading_deg": 0, "speed": 1.5}})";

TEST(SimPng, TheGamesRendererDrawsThePathsAndTheBallsWhereTheyStopped) {
  ASSERT_TRUE(testing::haveXvfbRun()) << "needs xvfb-run";
  TempFile scene(kScene);
  const std::string png = scene.path() + ".png";
  const testing::XvfbRun run =
      testing::runUnderXvfb(shellQuoted(NINEBALL_BINARY) + " sim " + shellQuoted(scene.path()) +
                                " --png " + shellQuoted(png) + " >/dev/null",
                            1280, 800);
  ASSERT_EQ(run.status, 0) << run.err;
  sf::Image image;
  ASSERT_TRUE(image.loadFromFile(png));
  std::remove(png.c_str());
  const auto parsed = io::parseScene(kScene);
  const Scene& s = std::get<Scene>(parsed);
  const SimResult r = simulate(s);
  const render::ViewTransform view(s.table, image.getSize().x, image.getSize().y);
  auto at = [&](Vec2 m) {
    const Vec2 p = view.toPixels(m);
    return image.getPixel(static_cast<unsigned>(std::lround(p.x)),
                          static_cast<unsigned>(std::lround(p.y)));
  };
  // Each ball whole where it stopped: its colour beside the number disc.
  // (Drawn number up, lit from above: each colour as the light shows it there.)
  for (const BallState& b : r.balls) {
    const Vec2 side = b.pos + Vec2{0.7 * s.physics.ball_radius, 0.0};
    EXPECT_TRUE(near(at(side), render::litColour(ballColour(b.id), 0.7, 0.0))) << "ball " << b.id;
  }
  // The 3's path runs along the x axis between where it started and where it stopped: its
  // rolling part (the end of its run) is solid red.
  const BallState& three = r.balls[1];
  ASSERT_EQ(three.id, 3);
  const Vec2 late{three.pos.x - 0.1, 0.0};
  ASSERT_GT(late.x, 0.3 + 2.0 * s.physics.ball_radius);
  EXPECT_TRUE(near(at(late), ballColour(3)));
}

TEST(SimPng, WithoutADisplayOrWithJsonlItIsRefused) {
  TempFile scene(kScene);
  const std::string png = scene.path() + ".png";
  const std::string cmd = "env -u DISPLAY " + shellQuoted(NINEBALL_BINARY) + " sim " +
                          shellQuoted(scene.path()) + " --png " + shellQuoted(png) +
                          " >/dev/null 2>/dev/null";
  const int raw = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 2);
  EXPECT_NE(access(png.c_str(), F_OK), 0) << "no picture without a display";
  const CliOutcome jsonl = runNineball("sim --jsonl - --png " + shellQuoted(png));
  EXPECT_EQ(jsonl.status, 2);
  EXPECT_NE(jsonl.err.find("--png draws one scene"), std::string::npos) << jsonl.err;
}

}  // namespace
}  // namespace nineball::testing
