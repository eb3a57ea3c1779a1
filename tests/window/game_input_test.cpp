// The mouse on the HUD: the tilt ring beside the spin icon raises and lowers the cue.
#include "window/game_input.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "render/hud_layout.hpp"
#include "window/computer_player.hpp"
#include "window/game_session.hpp"

namespace nineball::window {
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
}  // namespace nineball::window

namespace nineball::window {
namespace {

sf::Event key(sf::Keyboard::Key code, bool shift = false) {
  sf::Event e{};
  e.type = sf::Event::KeyPressed;
  e.key.code = code;
  e.key.shift = shift;
  return e;
}

sf::Event release(sf::Keyboard::Key code) {
  sf::Event e = key(code);
  e.type = sf::Event::KeyReleased;
  return e;
}

TEST(SpinKeys, LAndRGiveSideSpinTAndBTopAndBackCCentres) {
  GameSession s{MatchSetup{}};
  UiState ui;
  ComputerPlayer computer(1);
  GameInput input(s, ui, computer);
  const render::ViewTransform view(s.match().world().table().def, 1280, 800);
  auto press = [&](sf::Keyboard::Key k) {
    input.handle(key(k), view);
    input.handle(release(k), view);
  };
  press(sf::Keyboard::L);
  press(sf::Keyboard::L);
  EXPECT_NEAR(s.tip().x, -0.2, 1e-12);
  press(sf::Keyboard::R);
  EXPECT_NEAR(s.tip().x, -0.1, 1e-12);
  press(sf::Keyboard::T);
  EXPECT_NEAR(s.tip().y, 0.1, 1e-12);
  press(sf::Keyboard::B);
  press(sf::Keyboard::B);
  EXPECT_NEAR(s.tip().y, -0.1, 1e-12);
  for (int i = 0; i < 20; ++i) press(sf::Keyboard::R);
  EXPECT_LE(length(s.tip()), s.maxTip());  // held inside the useful range
  EXPECT_GT(s.tip().x, 0.0);
  press(sf::Keyboard::C);
  EXPECT_EQ(s.tip(), Vec2{});
}

TEST(ReplayKey, VReplaysTheLastShotAndAnyKeyReturns) {
  GameSession s{MatchSetup{}};
  UiState ui;
  ComputerPlayer computer(1);
  GameInput input(s, ui, computer);
  const render::ViewTransform view(s.match().world().table().def, 1280, 800);
  input.handle(key(sf::Keyboard::V), view);
  input.handle(release(sf::Keyboard::V), view);
  EXPECT_FALSE(s.replaying());  // nothing to replay before the break
  ASSERT_TRUE(s.shoot());
  for (int i = 0; i < 60 * 120 && s.phase() == Phase::Rolling; ++i) s.advance(1.0 / 60.0);
  input.handle(key(sf::Keyboard::V, true), view);
  input.handle(release(sf::Keyboard::V), view);
  ASSERT_TRUE(s.replaying());
  EXPECT_NE(s.status().find("Slow replay"), std::string::npos);
  const double heading = s.heading();
  input.handle(key(sf::Keyboard::Left), view);  // returns, and does not aim
  EXPECT_FALSE(s.replaying());
  EXPECT_EQ(s.heading(), heading);
}

}  // namespace
}  // namespace nineball::window
