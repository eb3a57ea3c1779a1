// The mouse on the HUD: the tilt ring beside the spin icon raises and lowers the cue.
#include "app/game/game_input.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "app/game/computer_player.hpp"
#include "app/game/game_session.hpp"
#include "render/hud_layout.hpp"

namespace nineball::app {
namespace {

sf::Event mouse(sf::Event::EventType type, Vec2 px) {
  sf::Event e{};
  e.type = type;
  if (type == sf::Event::MouseMoved) {
    e.mouseMove.x = static_cast<int>(std::lround(px.x));
    e.mouseMove.y = static_cast<int>(std::lround(px.y));
  } else {
    e.mouseButton.button = sf::Mouse::Left;
    e.mouseButton.x = static_cast<int>(std::lround(px.x));
    e.mouseButton.y = static_cast<int>(std::lround(px.y));
  }
  return e;
}

TEST(TiltRing, AClickAndADragOnTheRingTiltTheCue) {
  GameSession s{MatchSetup{}};
  UiState ui;
  ComputerPlayer computer(1);
  GameInput input(s, ui, computer);
  const render::ViewTransform view(s.match().world().table().def, 1280, 800);
  const render::HudLayout layout = render::HudLayout::of(view);
  const double mid = 0.5 * (layout.tilt_inner + layout.tilt_outer);
  auto on_ring = [&](double deg) {
    return layout.spin_centre + render::HudLayout::tiltDirection(degToRad(deg)) * mid;
  };
  // A pixel is a degree or so at this size.
  constexpr double kPixelDeg = 2.0;
  input.handle(mouse(sf::Event::MouseButtonPressed, on_ring(30.0)), view);
  EXPECT_NEAR(radToDeg(s.elevation()), 30.0, kPixelDeg);
  input.handle(mouse(sf::Event::MouseMoved, on_ring(10.0)), view);
  EXPECT_NEAR(radToDeg(s.elevation()), 10.0, kPixelDeg);
  // Dragged past the top the cue stops at its steepest.
  input.handle(mouse(sf::Event::MouseMoved, on_ring(85.0)), view);
  EXPECT_DOUBLE_EQ(radToDeg(s.elevation()), GameSession::kMaxElevationDeg);
  input.handle(mouse(sf::Event::MouseButtonReleased, on_ring(85.0)), view);
  // Moving after the release aims again and leaves the tilt alone.
  input.handle(mouse(sf::Event::MouseMoved, on_ring(5.0)), view);
  EXPECT_DOUBLE_EQ(radToDeg(s.elevation()), GameSession::kMaxElevationDeg);
  EXPECT_EQ(ui.drag, Drag::None);
}

TEST(TiltRing, OnlyTheRingTilts) {
  const render::ViewTransform view(TableDef{}, 1280, 800);
  const render::HudLayout layout = render::HudLayout::of(view);
  const double mid = 0.5 * (layout.tilt_inner + layout.tilt_outer);
  const Vec2 c = layout.spin_centre;
  EXPECT_TRUE(layout.tiltAt(c + Vec2{-mid, 0.0}));
  EXPECT_FALSE(layout.tiltAt(c));                                // the icon sets the tip
  EXPECT_FALSE(layout.tiltAt(c + Vec2{mid, 0.0}));               // right of the icon
  EXPECT_FALSE(layout.tiltAt(c + Vec2{-mid * 0.7, mid * 0.7}));  // below it
  EXPECT_FALSE(layout.tiltAt(c + Vec2{-3.0 * mid, 0.0}));        // far off
}

}  // namespace
}  // namespace nineball::app
