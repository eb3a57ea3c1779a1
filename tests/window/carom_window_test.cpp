// Three-cushion in the real game window under Xvfb: the carom table without pockets (cloth where
// a pool table has its corner pockets), the three balls in their colours where the physics left
// them after a scripted point, and the HUD's count showing the point.
#include <gtest/gtest.h>
#include <unistd.h>

#include <SFML/Graphics/Image.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "nineball/match.hpp"
#include "render/palette.hpp"
#include "render/view_transform.hpp"
#include "support/xvfb_run.hpp"
#include "window/script_screenshot.hpp"

namespace nineball::window {
namespace {

using nineball::testing::kHeight;
using nineball::testing::kWidth;

// The master's opening shot of seed 1 (nineball match, both players ai:master): a point off
// three cushions, the white onto the red first.
TurnInput scoringOpening() {
  TurnInput t;
  t.shot = Shot::withSpeed(-7.344776203153136, 3.4371906390450406);
  t.shot.tip = {0.3534331495053398, -0.20163835515660183};
  return t;
}

TEST(CaromWindow, ShowsTheCaromTableTheThreeBallsAndAScoredPoint) {
  ASSERT_TRUE(testing::haveXvfbRun())
      << "xvfb-run not found: install xvfb and xauth (bash scripts/setup.sh)";
  std::ostringstream script;
  {
    const TurnInput t = scoringOpening();
    script.precision(17);
    script << R"({"game": "three-cushion", "seed": 1, "turns": [{"heading_deg": )"
           << radToDeg(t.shot.heading_rad) << R"(, "speed": )" << t.shot.speed << R"(, "tip": [)"
           << t.shot.tip.x << ", " << t.shot.tip.y << "]}]}";
  }
  sf::Image image;
  const testing::XvfbRun run =
      testing::screenshotOfScript(script.str(), "carom", kWidth, kHeight, image);
  ASSERT_EQ(run.status, 0) << run.err;
  ASSERT_EQ(image.getSize(), sf::Vector2u(kWidth, kHeight));

  // The same turn headless: where the balls stopped, and that it scored.
  MatchSetup setup;
  setup.setGame(rules::Game::ThreeCushion);
  Match match(setup);
  const TurnRecord turn = match.play(scoringOpening());
  ASSERT_EQ(turn.verdict.points[0], 1);

  const render::ViewTransform view(TableDef::carom(), kWidth, kHeight);
  auto at = [&](Vec2 m) {
    const Vec2 p = view.toPixels(m);
    return image.getPixel(static_cast<unsigned>(std::lround(p.x)),
                          static_cast<unsigned>(std::lround(p.y)));
  };
  // Cloth, not a pocket, in each corner (a pool table's pocket is black there).
  const double r = match.world().physics().ball_radius;
  for (Vec2 corner : {Vec2{1.42 - r, 0.71 - r}, Vec2{-1.42 + r, -0.71 + r}, Vec2{0.0, 0.71 - r}}) {
    const sf::Color c = at(corner);
    EXPECT_GT(c.g, c.r + 30) << "not cloth at " << corner.x << ", " << corner.y;
  }
  // Each ball in its colour, read beside its middle (the cue balls' spots sit at the poles).
  for (const BallState& b : match.balls()) {
    const sf::Color c = at(b.pos + Vec2{0.5 * r, 0.0});
    SCOPED_TRACE("ball " + std::to_string(b.id));
    const bool white = c.r > 170 && c.g > 170 && c.b > 160;
    const bool yellow = c.r > 170 && c.g > 120 && c.b < 100;
    const bool red = c.r > 140 && c.g < 70 && c.b < 70;
    EXPECT_TRUE(b.id == 0   ? white
                : b.id == 1 ? yellow
                            : red)
        << "(" << int(c.r) << ", " << int(c.g) << ", " << int(c.b) << ")";
  }
  // The count in the top band's middle, in the colour of a point.
  const render::PixelRect band = view.topBand();
  int green = 0;
  for (unsigned y = static_cast<unsigned>(band.top + band.height / 2.0);
       y < static_cast<unsigned>(band.top + band.height); ++y) {
    for (unsigned x = static_cast<unsigned>(band.left + band.width * 0.3);
         x < static_cast<unsigned>(band.left + band.width * 0.7); ++x) {
      const sf::Color c = image.getPixel(x, y);
      if (c.g > 180 && c.r < 170 && c.b < 170) ++green;
    }
  }
  EXPECT_GT(green, 60) << "no \"POINT\" in the count";
}

}  // namespace
}  // namespace nineball::window
