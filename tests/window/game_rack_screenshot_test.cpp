// The eight- and ten-ball racks in the real game window under Xvfb: each ball's colour where
// the physics racks it, a stripe's band in its colour and white above and below it.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <SFML/Graphics/Image.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "render/ball_spin.hpp"
#include "render/palette.hpp"
#include "render/view_transform.hpp"
#include "support/xvfb_run.hpp"
#include "window/game_session.hpp"

namespace nineball::window {
namespace {

using nineball::testing::shellWord;

using nineball::testing::kHeight;
using nineball::testing::kWidth;
constexpr int kTolerance = 24;  // per channel; the balls are drawn without antialiasing

int shoot(const std::string& args) {
  return testing::runGameUnderXvfb(args, kWidth, kHeight).status;
}

bool near(sf::Color c, render::Rgb want) {
  return std::abs(c.r - want.r) <= kTolerance && std::abs(c.g - want.g) <= kTolerance &&
         std::abs(c.b - want.b) <= kTolerance;
}

std::string show(sf::Color c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

void expectRack(rules::Game game, std::size_t balls) {
  SCOPED_TRACE(rules::gameName(game));
  const std::string png = "/tmp/nineball-test-rack-" + std::string(rules::gameName(game)) + "-" +
                          std::to_string(getpid()) + ".png";
  ASSERT_EQ(
      shoot(std::string("--game ") + rules::gameName(game) + " --screenshot " + shellWord(png)), 0);
  sf::Image image;
  ASSERT_TRUE(image.loadFromFile(png));
  std::remove(png.c_str());
  ASSERT_EQ(image.getSize(), sf::Vector2u(kWidth, kHeight));
  MatchSetup setup;
  setup.game = game;
  const GameSession session(setup);
  const double r = session.match().world().physics().ball_radius;
  const render::ViewTransform view(TableDef{}, kWidth, kHeight);
  auto at = [&](Vec2 m) {
    const Vec2 p = view.toPixels(m);
    return image.getPixel(static_cast<unsigned>(std::lround(p.x)),
                          static_cast<unsigned>(std::lround(p.y)));
  };
  std::size_t checked = 0, stripes = 0;
  for (const BallState& b : session.ballsToDraw()) {
    if (b.pocket || b.id == kCueBall) continue;
    ++checked;
    const render::Rgb colour = render::ballColour(b.id);
    // Left and right of the number disc: the ball's colour (a stripe's band).
    // A racked ball has not turned: its number faces up, each colour lit where it is (at the
    // centre of the pixel read, the light changing fast towards the rim).
    auto lit = [&](render::Rgb surface, Vec2 s) {
      const Vec2 c = view.toPixels(b.pos), p = view.toPixels(b.pos + s * r);
      const double r_px = view.px(r);
      return render::litColour(surface, (std::lround(p.x) + 0.5 - c.x) / r_px,
                               -(std::lround(p.y) + 0.5 - c.y) / r_px);
    };
    for (Vec2 s : {Vec2{0.72, 0.0}, Vec2{-0.72, 0.0}}) {
      const sf::Color c = at(b.pos + s * r);
      EXPECT_TRUE(near(c, lit(colour, s))) << "ball " << b.id << " side: " << show(c);
    }
    // Above and below the disc: white past a stripe's band, the colour on a solid.
    const render::Rgb cap = render::isStripe(b.id) ? render::kNumberDisc : colour;
    if (render::isStripe(b.id)) ++stripes;
    for (Vec2 s : {Vec2{0.0, 0.78}, Vec2{0.0, -0.78}}) {
      const sf::Color c = at(b.pos + s * r);
      EXPECT_TRUE(near(c, lit(cap, s))) << "ball " << b.id << " cap: " << show(c);
    }
  }
  EXPECT_EQ(checked, balls);
  EXPECT_EQ(stripes, game == rules::Game::EightBall ? 7u : 2u);
}

TEST(GameRackScreenshots, EightAndTenBallRacksShowEveryBallWhereThePhysicsPutsIt) {
  ASSERT_EQ(std::system("command -v xvfb-run >/dev/null 2>&1"), 0)
      << "xvfb-run not found: install xvfb and xauth (bash scripts/setup.sh)";
  expectRack(rules::Game::EightBall, 15);
  expectRack(rules::Game::TenBall, 10);
}

}  // namespace
}  // namespace nineball::window
