// Where the dialogs go: the push-out choice and the rack's end leave the cue ball in sight.
#include "render/hud_layout.hpp"

#include <gtest/gtest.h>

namespace nineball::render {
namespace {

TEST(HudLayout, ChoiceDialogsNeverCoverTheCueBall) {
  const TableDef table;
  constexpr double kR = 0.028575;
  for (const auto& [w, h] : {std::pair{640.0, 480.0},
                             {1126.0, 704.0},
                             {1280.0, 800.0},
                             {3840.0, 2160.0},
                             {500.0, 700.0}}) {
    const ViewTransform view(table, w, h);
    for (const DialogLook& look : {DialogLook::across(0.36), DialogLook::across(0.5)}) {
      // Every spot a cue ball can rest on, on a 2 cm grid.
      for (double x = -table.length / 2 + kR; x <= table.length / 2 - kR; x += 0.02) {
        for (double y = -table.width / 2 + kR; y <= table.width / 2 - kR; y += 0.02) {
          const HudLayout layout = HudLayout::of(view, look, {Vec2{x, y}});
          const PixelRect p = layout.panel;
          const Vec2 c = view.toPixels({x, y});
          const double r = view.px(kR);
          const bool covered = c.x + r > p.left && c.x - r < p.left + p.width && c.y + r > p.top &&
                               c.y - r < p.top + p.height;
          ASSERT_FALSE(covered) << w << "x" << h << " cue ball at " << x << ", " << y;
        }
      }
    }
  }
}

TEST(HudLayout, TheDialogsButtonsAreInsideItsPanel) {
  const ViewTransform view(TableDef{}, 1280, 800);
  for (const DialogLook& look :
       {DialogLook::wide(), DialogLook::box(), DialogLook::across(0.36), DialogLook::across(0.5)}) {
    const HudLayout l = HudLayout::of(view, look, {Vec2{0.3, 0.2}});
    for (const PixelRect& b : {l.button_left, l.button_right}) {
      EXPECT_GE(b.left, l.panel.left);
      EXPECT_LE(b.left + b.width, l.panel.left + l.panel.width);
      EXPECT_GE(b.top, l.panel.top);
      EXPECT_LE(b.top + b.height, l.panel.top + l.panel.height);
    }
  }
}

TEST(HudLayout, TheChoiceStripHidesNoBallWhereItCanBePlacedSo) {
  // Balls by both long cushions, where the strip used to go, and a free band across the
  // middle: the strip goes there.
  const TableDef table;
  const std::vector<Vec2> balls = {{-0.3, 0.55}, {0.2, -0.55}, {0.5, 0.5},
                                   {-0.6, -0.5}, {0.0, 0.4},   {0.1, -0.4}};
  for (const auto& [w, h] : {std::pair{1280.0, 800.0}, {640.0, 480.0}, {3840.0, 2160.0}}) {
    const ViewTransform view(table, w, h);
    for (const DialogLook& look : {DialogLook::across(0.36), DialogLook::across(0.5)}) {
      const HudLayout layout = HudLayout::of(view, look, balls);
      EXPECT_EQ(HudLayout::hiddenBy(view, layout.panel, balls), 0) << w << "x" << h;
    }
  }
}

TEST(HudLayout, WhenEveryPlaceHidesABallTheStripHidesTheFewest) {
  // A ball every 10 cm down the middle of the table: any strip across it hides some; the
  // bands above and below the table hide none.
  const TableDef table;
  std::vector<Vec2> balls;
  for (double y = -0.6; y <= 0.6; y += 0.1) balls.push_back({0.0, y});
  const ViewTransform view(table, 1280, 800);
  const HudLayout layout = HudLayout::of(view, DialogLook::across(0.36), balls);
  PixelRect along_cushion = layout.panel;
  along_cushion.top = view.toPixels({0.0, table.width / 2.0 - 0.04}).y;
  EXPECT_LT(HudLayout::hiddenBy(view, layout.panel, balls),
            HudLayout::hiddenBy(view, along_cushion, balls));
}

}  // namespace
}  // namespace nineball::render

namespace nineball::render {
namespace {

TEST(HudLayout, TheSpinLabelsLeaveRoomForTheCuesMarkerOnTheRing) {
  // The marker at a level cue points left from the icon, past the ring: the labels end a gap
  // before its tip at every size.
  for (const auto& [w, h] : {std::pair{640.0, 480.0}, {1280.0, 800.0}, {3840.0, 2160.0}}) {
    const HudLayout l = HudLayout::of(ViewTransform(TableDef{}, w, h));
    const double marker_tip =
        l.spin_centre.x - l.tilt_outer - HudLayout::kTiltMarkReach * l.spin_radius;
    EXPECT_LT(l.spin_labels_right, marker_tip - 2.0) << w << "x" << h;
    EXPECT_GT(l.message.width, 0.0) << w << "x" << h;
  }
}

TEST(HudLayout, ThreeButtonsSitSideBySideInsideTheStrip) {
  for (const auto& [w, h] : {std::pair{640.0, 480.0}, {1280.0, 800.0}}) {
    const HudLayout l =
        HudLayout::of(ViewTransform(TableDef{}, w, h), DialogLook::across(0.36), {}, true);
    EXPECT_GE(l.button_left.left, l.panel.left);
    EXPECT_LT(l.button_left.left + l.button_left.width, l.button_middle.left);
    EXPECT_LT(l.button_middle.left + l.button_middle.width, l.button_right.left);
    EXPECT_LE(l.button_right.left + l.button_right.width, l.panel.left + l.panel.width);
  }
}

}  // namespace
}  // namespace nineball::render
