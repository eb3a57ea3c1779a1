#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <string>

#include "render/ball_painter.hpp"
#include "render/fonts.hpp"
#include "render/hud_layout.hpp"
#include "render/hud_state.hpp"
#include "render/triangle_batch.hpp"

namespace nineball::render {

/// The players' corners, the ball on, the power gauge, the spin icon, the messages and the
/// dialogs.
class HudPainter {
 public:
  explicit HudPainter(const Fonts& fonts) : fonts_(fonts), balls_(fonts.bold) {}

  void draw(sf::RenderTarget& target, const ViewTransform& view, const HudState& hud);

 private:
  enum class Align { Left, Centre, Right };
  /// Draws one line of text with its top-left (Left), top-centre or top-right at `at`,
  /// smaller if it would be wider than `max_width` pixels (0: no limit).
  void text(sf::RenderTarget& target, const std::string& s, Vec2 at, double size, sf::Color colour,
            Align align = Align::Left, bool bold = false, double max_width = 0.0);
  void drawPlayers(sf::RenderTarget& target, const ViewTransform& view, const HudState& hud,
                   const HudLayout& layout);
  void drawBottom(sf::RenderTarget& target, const HudState& hud, const HudLayout& layout);
  void drawOverlay(sf::RenderTarget& target, const HudState& hud, const HudLayout& layout);

  const Fonts& fonts_;
  BallPainter balls_;
  TriangleBatch batch_;
};

}  // namespace nineball::render
