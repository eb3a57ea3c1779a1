// Snooker in the real game window under Xvfb: the full-size table with its baulk line and D,
// the six colours on their spots and the fifteen reds in their triangle, the pockets' openings,
// and the scoreboard's line (the break and the points remaining) where pool shows its tray.
#include <gtest/gtest.h>
#include <unistd.h>

#include <SFML/Graphics/Image.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "nineball/games.hpp"
#include "nineball/match.hpp"
#include "nineball/table_markings.hpp"
#include "render/view_transform.hpp"
#include "support/xvfb_run.hpp"
#include "window/script_screenshot.hpp"

namespace nineball::window {
namespace {

using nineball::testing::kHeight;
using nineball::testing::kWidth;

// The colour a snooker ball of this id must read as, by its dominant channels.
bool looksLike(int id, const sf::Color& c) {
  const int r = c.r, g = c.g, b = c.b;
  if (id >= 1 && id <= 15) return r > 140 && g < 70 && b < 80;  // red
  switch (id) {
    case 16:
      return r > 170 && g > 150 && b < 100;  // yellow
    case 17:
      return g > r + 30 && g > b && g < 160;  // green
    case 18:
      return r > g && g > b && r > 70 && r < 170;  // brown
    case 19:
      return b > r + 60 && b > g + 40;  // blue
    case 20:
      return r > 180 && b > 110 && g < r - 40;  // pink
    case 21:
      return r < 60 && g < 60 && b < 60;  // black
    default:
      return false;
  }
}

TEST(SnookerWindow, ShowsTheSnookerTableTheBallsOnTheirSpotsAndTheScoreboard) {
  ASSERT_TRUE(testing::haveXvfbRun())
      << "xvfb-run not found: install xvfb and xauth (bash scripts/setup.sh)";
  sf::Image image;
  const testing::XvfbRun run = testing::screenshotOfScript(
      R"({"game": "snooker", "seed": 1, "turns": []})", "snooker", kWidth, kHeight, image);
  ASSERT_EQ(run.status, 0) << run.err;
  ASSERT_EQ(image.getSize(), sf::Vector2u(kWidth, kHeight));

  MatchSetup setup;
  setup.setGame(rules::Game::Snooker);
  const Match match(setup);
  const TableDef table = *TableDef::named("snooker");
  const render::ViewTransform view(table, kWidth, kHeight);
  auto at = [&](Vec2 m) {
    const Vec2 p = view.toPixels(m);
    return image.getPixel(static_cast<unsigned>(std::lround(p.x)),
                          static_cast<unsigned>(std::lround(p.y)));
  };
  const double r = match.world().physics().ball_radius;
  // Every object ball in its colour where the rack put it (read beside its middle).
  int balls = 0;
  for (const BallState& b : match.balls()) {
    if (b.id == kCueBall || b.pocket) continue;
    ++balls;
    const sf::Color c = at(b.pos + Vec2{0.4 * r, 0.0});
    EXPECT_TRUE(looksLike(b.id, c))
        << "ball " << b.id << " reads (" << int(c.r) << ", " << int(c.g) << ", " << int(c.b) << ")";
  }
  EXPECT_EQ(balls, 21);
  // The baulk line and the D's arc are drawn lighter than the cloth beside them.
  const SnookerLayout l = SnookerLayout::of(table);
  auto lighter = [&](Vec2 on, Vec2 beside) {
    const sf::Color a = at(on), b = at(beside);
    return a.r + a.g + a.b > b.r + b.g + b.b + 40;
  };
  EXPECT_TRUE(lighter({l.baulk_x, 0.6}, {l.baulk_x + 0.02, 0.6})) << "no baulk line";
  const Vec2 arc = l.brown + Vec2{-std::cos(0.5), std::sin(0.5)} * l.d_radius;
  EXPECT_TRUE(lighter(arc, arc + Vec2{0.02, 0.0})) << "no D";
  // The corner pockets are open (dark) just beyond the corner of the cloth.
  for (Vec2 corner : {Vec2{table.length / 2.0, table.width / 2.0},
                      Vec2{-table.length / 2.0, -table.width / 2.0}}) {
    const sf::Color c = at(corner * 1.004);
    EXPECT_LT(c.r + c.g + c.b, 120) << "no pocket at " << corner.x << ", " << corner.y;
  }
  // The scoreboard's line (break and points remaining) in the top band's lower middle: light
  // text where pool draws its tray of balls.
  const render::PixelRect band = view.topBand();
  int light = 0;
  for (unsigned y = static_cast<unsigned>(band.top + band.height / 2.0);
       y < static_cast<unsigned>(band.top + band.height); ++y) {
    for (unsigned x = static_cast<unsigned>(band.left + band.width * 0.35);
         x < static_cast<unsigned>(band.left + band.width * 0.65); ++x) {
      const sf::Color c = image.getPixel(x, y);
      if (c.r > 200 && c.g > 200 && c.b > 200) ++light;
    }
  }
  EXPECT_GT(light, 80) << "no scoreboard line";
}

}  // namespace
}  // namespace nineball::window
