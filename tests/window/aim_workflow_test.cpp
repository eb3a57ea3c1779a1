// The aim workflow: aim, lock the line (X), fine-tune it (Shift with the pointer: a fiftieth of
// a degree per pixel; the wheel a hundredth, with Shift a tenth), and nothing else moves it;
// zoom 1x-4x round the cue ball or the pointer; the aim guide full, the cue ball's line alone,
// or off.
#include <gtest/gtest.h>

#include <cmath>

#include "render/hud_layout.hpp"
#include "window/game_rolling.hpp"
#include "window/input_events.hpp"
#include "window/settings.hpp"

namespace nineball::window {
namespace {

sf::Event shifted(sf::Event e) {
  e.key.shift = true;
  return e;
}

TEST(AimWorkflow, ALockedLineStaysWhereverThePointerGoes) {
  InputTable t;
  const Vec2 cue = t.s.cuePosition();
  t.mouseTo(cue + Vec2{0.8, 0.1});
  const double aimed = t.s.heading();
  t.tap(sf::Keyboard::X);
  ASSERT_TRUE(t.ui.aim_locked);
  for (Vec2 to : {Vec2{0.0, 0.5}, Vec2{-0.5, -0.4}, Vec2{1.0, 0.0}}) {
    t.mouseTo(to);
    EXPECT_DOUBLE_EQ(t.s.heading(), aimed);
  }
  // The arrows still fine-tune a locked line; X unlocks and the pointer aims again.
  t.tap(sf::Keyboard::Left);
  EXPECT_NEAR(radToDeg(t.s.heading() - aimed), 0.1, 1e-9);
  t.tap(sf::Keyboard::X);
  t.mouseTo(cue + Vec2{0.0, 0.4});
  EXPECT_NEAR(t.s.heading(), kPi / 2.0, 1e-2);
}

TEST(AimWorkflow, ShiftWithThePointerTurnsTheLineAFiftiethOfADegreePerPixel) {
  InputTable t;
  const Vec2 start = t.view.toPixels(t.s.cuePosition() + Vec2{0.8, 0.0});
  t.pointerAt(start);
  const double aimed = t.s.heading();
  t.input.handle(shifted(key(sf::Keyboard::LShift)), t.view);
  t.pointerAt(start + Vec2{1.0, 0.0});  // a pixel rightwards: a fiftieth of a degree clockwise
  const double from = t.s.heading();
  EXPECT_NEAR(radToDeg(from - aimed), -0.02, 1e-9);
  t.pointerAt(start + Vec2{51.0, 40.0});  // 50 px rightwards (the up-down travel is not read)
  EXPECT_NEAR(radToDeg(t.s.heading() - from), -1.0, 1e-9);
  EXPECT_TRUE(t.ui.aim_locked);  // fine-tuning locks the line
  const double tuned = t.s.heading();
  t.input.handle(release(sf::Keyboard::LShift), t.view);
  t.pointerAt(start + Vec2{-300.0, 200.0});  // let go: the line stays as tuned
  EXPECT_DOUBLE_EQ(t.s.heading(), tuned);
}

TEST(AimWorkflow, TheWheelTurnsAHundredthOrWithShiftATenthOfADegree) {
  InputTable t;
  const double h0 = t.s.heading();
  t.input.handle(wheel(2.0f), t.view);
  EXPECT_NEAR(radToDeg(t.s.heading() - h0), 0.02, 1e-9);
  t.input.handle(shifted(key(sf::Keyboard::LShift)), t.view);
  t.input.handle(wheel(-1.0f), t.view);
  EXPECT_NEAR(radToDeg(t.s.heading() - h0), -0.08, 1e-9);
}

TEST(AimWorkflow, ANewTurnUnlocksTheLine) {
  InputTable t;
  t.tap(sf::Keyboard::X);
  ASSERT_TRUE(t.ui.aim_locked);
  ASSERT_TRUE(t.s.shoot());
  t.input.update(1.0 / 60.0);
  ASSERT_TRUE(roll(t.s));
  t.input.update(1.0 / 60.0);
  EXPECT_FALSE(t.ui.aim_locked);
}

TEST(AimWorkflow, ZAndCtrlWheelZoomOneToFourTimesRoundTheCueBallOrThePointer) {
  InputTable t;
  t.tap(sf::Keyboard::Z);
  EXPECT_EQ(t.ui.zoom, 2.0);
  EXPECT_FALSE(t.ui.zoom_at);  // round the cue ball
  for (int i = 0; i < 5; ++i) t.tap(sf::Keyboard::Z);
  EXPECT_EQ(t.ui.zoom, 4.0);
  for (int i = 0; i < 5; ++i) t.tap(sf::Keyboard::Z, true);
  EXPECT_EQ(t.ui.zoom, 1.0);
  // Ctrl with the wheel: closer at the pointer.
  sf::Event ctrl = key(sf::Keyboard::LControl);
  ctrl.key.control = true;
  t.input.handle(ctrl, t.view);
  sf::Event notch = wheel(1.0f);
  const Vec2 px = t.view.toPixels({0.5, 0.2});
  notch.mouseWheelScroll.x = static_cast<int>(std::lround(px.x));
  notch.mouseWheelScroll.y = static_cast<int>(std::lround(px.y));
  const double heading = t.s.heading();
  t.input.handle(notch, t.view);
  EXPECT_EQ(t.ui.zoom, 2.0);
  ASSERT_TRUE(t.ui.zoom_at);
  EXPECT_NEAR(t.ui.zoom_at->x, 0.5, 0.01);
  EXPECT_NEAR(t.ui.zoom_at->y, 0.2, 0.01);
  EXPECT_EQ(t.s.heading(), heading);  // zooming does not aim
}

TEST(AimWorkflow, AZoomedViewMapsThePointerToTheTableAndKeepsTheHudInPlace) {
  const render::ViewTransform base(TableDef{}, 1280, 800);
  const render::ViewTransform z = base.zoomed(3.0, {0.2, -0.1});
  EXPECT_DOUBLE_EQ(z.scale(), 3.0 * base.scale());
  // The focus is drawn where the table's centre was; pixels and metres round-trip.
  const Vec2 c = z.toPixels({0.2, -0.1}), centre = base.toPixels({0.0, 0.0});
  EXPECT_NEAR(c.x, centre.x, 1e-9);
  EXPECT_NEAR(c.y, centre.y, 1e-9);
  const Vec2 back = z.toWorld(z.toPixels({0.61, 0.33}));
  EXPECT_NEAR(back.x, 0.61, 1e-12);
  EXPECT_NEAR(back.y, 0.33, 1e-12);
  // A focus near a corner is held back so that the view stays on the rails.
  const render::ViewTransform corner = base.zoomed(2.0, {5.0, 5.0});
  EXPECT_LT(corner.focus().x, 2.54 / 2.0);
  EXPECT_LT(corner.focus().y, 1.27 / 2.0);
  // The HUD's bands and controls do not move with the zoom.
  const render::PixelRect a = base.bottomBand(), b = z.bottomBand();
  EXPECT_EQ(a.top, b.top);
  EXPECT_EQ(a.height, b.height);
  const render::HudLayout la = render::HudLayout::of(base), lb = render::HudLayout::of(z);
  EXPECT_EQ(la.spin_centre, lb.spin_centre);
  // The pointer aims through the zoomed view: at the point it is over.
  InputTable t;
  const Vec2 target = t.s.cuePosition() + Vec2{0.3, 0.3};
  t.view = t.view.zoomed(2.5, t.s.cuePosition());
  t.mouseTo(target);
  EXPECT_NEAR(t.s.heading(), kPi / 4.0, 1e-3);
}

TEST(AimWorkflow, TheGuideIsFullTheCueBallsLineAloneOrOff) {
  EXPECT_EQ(nextGuide(GuideLength::Long), GuideLength::CueLine);
  EXPECT_EQ(nextGuide(GuideLength::CueLine), GuideLength::Off);
  EXPECT_EQ(nextGuide(GuideLength::Off), GuideLength::Short);
  EXPECT_EQ(guideLengthFactor(GuideLength::CueLine), 0.0);
  // Kept between runs by name.
  for (GuideLength g : kGuideStyles) {
    Settings s;
    s.guide = g;
    std::string warnings;
    EXPECT_EQ(settingsFromJson(settingsToJson(s), warnings).guide, g) << guideLengthName(g);
    EXPECT_EQ(warnings, "");
  }
  // G asks the window for the next style.
  InputTable t;
  t.tap(sf::Keyboard::G);
  EXPECT_TRUE(t.input.requests().cycle_guide);
}

}  // namespace
}  // namespace nineball::window
