// The aim guide's foul warning is read over the balls, not hidden by them: under Xvfb, with the
// guide running through the 3 to the ball on, the words' box covers a ball placed beside the
// ghost ball.
#include <gtest/gtest.h>

#include <SFML/Graphics/Image.hpp>
#include <cmath>

#include "nineball/match.hpp"
#include "render/view_transform.hpp"
#include "support/xvfb_run.hpp"
#include "window/script_screenshot.hpp"

namespace nineball::window {
namespace {

using nineball::testing::kHeight;
using nineball::testing::kWidth;

TEST(GuideFoulWindow, TheWarningIsDrawnOverTheBalls) {
  ASSERT_TRUE(testing::haveXvfbRun())
      << "xvfb-run not found: install xvfb and xauth (bash scripts/setup.sh)";
  const double r = MatchSetup{}.physics.ball_radius;
  // The cue ball aims at the 1 (the ball on) straight through the 3: a foul, its words beside
  // the ghost ball, below the line, where the 5 stands.
  const Vec2 five{0.3 + 6.0 * r, -1.8 * r};
  const std::string script =
      R"({"balls": [{"id": 0, "x": -0.6, "y": 0}, {"id": 3, "x": 0.3, "y": 0},
                    {"id": 1, "x": 0.8, "y": 0}, {"id": 5, "x": )" +
      std::to_string(five.x) + R"(, "y": )" + std::to_string(five.y) + R"(}], "turns": []})";
  sf::Image image;
  const testing::XvfbRun run =
      testing::screenshotOfScript(script, "guide-foul", kWidth, kHeight, image);
  ASSERT_EQ(run.status, 0) << run.err;
  const render::ViewTransform view(TableDef{}, kWidth, kHeight);
  // The 5's orange beside its number disc: hidden under the warning's dark box or its words.
  const Vec2 px = view.toPixels(five + Vec2{0.6 * r, 0.0});
  const sf::Color c = image.getPixel(static_cast<unsigned>(std::lround(px.x)),
                                     static_cast<unsigned>(std::lround(px.y)));
  const bool orange = c.r > 150 && c.g > 60 && c.g < 180 && c.b < 70;
  EXPECT_FALSE(orange) << "the 5 shows through the warning: (" << int(c.r) << ", " << int(c.g)
                       << ", " << int(c.b) << ")";
  // And the 5 is there: its top, above the warning's box, shows.
  const Vec2 far = view.toPixels(five + Vec2{0.0, 0.75 * r});
  const sf::Color below = image.getPixel(static_cast<unsigned>(std::lround(far.x)),
                                         static_cast<unsigned>(std::lround(far.y)));
  EXPECT_GT(below.r, 150) << "no ball at the 5's place";
}

}  // namespace
}  // namespace nineball::window
