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
    for (Overlay overlay : {Overlay::PushOutChoice, Overlay::GameOver}) {
      // Every spot a cue ball can rest on, on a 2 cm grid.
      for (double x = -table.length / 2 + kR; x <= table.length / 2 - kR; x += 0.02) {
        for (double y = -table.width / 2 + kR; y <= table.width / 2 - kR; y += 0.02) {
          const HudLayout layout = HudLayout::of(view, overlay, Vec2{x, y});
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
  for (Overlay overlay :
       {Overlay::Help, Overlay::ConfirmQuit, Overlay::PushOutChoice, Overlay::GameOver}) {
    const HudLayout l = HudLayout::of(view, overlay, Vec2{0.3, 0.2});
    for (const PixelRect& b : {l.button_left, l.button_right}) {
      EXPECT_GE(b.left, l.panel.left);
      EXPECT_LE(b.left + b.width, l.panel.left + l.panel.width);
      EXPECT_GE(b.top, l.panel.top);
      EXPECT_LE(b.top + b.height, l.panel.top + l.panel.height);
    }
  }
}

}  // namespace
}  // namespace nineball::render
