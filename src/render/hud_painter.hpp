#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <string>
#include <vector>

#include "render/ball_painter.hpp"
#include "render/fonts.hpp"
#include "render/hud_layout.hpp"
#include "render/hud_state.hpp"
#include "render/triangle_batch.hpp"

namespace nineball::render {

/// A line of text as drawn, or a ball of the tray ("on table 3", "pocketed 5"): its box and the
/// room it was given (pixels).
struct DrawnText {
  std::string text;
  PixelRect box;
  PixelRect room;
};

/// The players' corners, the ball on, the power gauge, the spin icon, the messages and the
/// dialogs.
class HudPainter {
 public:
  explicit HudPainter(const Fonts& fonts) : fonts_(fonts), balls_(fonts.bold) {}
  /// The set of balls its icons show.
  void setLooks(BallLooks looks) {
    looks_ = looks;
    balls_.setLooks(looks);
  }

  void draw(sf::RenderTarget& target, const ViewTransform& view, const HudState& hud);
  /// Only the dialog of `hud` (its `dialog`), laid out as draw() would, its texts added to the
  /// last draw's.
  void drawDialog(sf::RenderTarget& target, const ViewTransform& view, const HudState& hud);
  /// Every line of text and tray ball the last draw put on screen, for checks that nothing
  /// spills or overlaps.
  const std::vector<DrawnText>& drawnTexts() const { return drawn_; }

 private:
  enum class Align { Left, Centre, Right };
  /// Draws one line of text with its top-left (Left), top-centre or top-right at `at`,
  /// smaller if it would be wider than the room's width; returns its glyphs' box.
  PixelRect text(sf::RenderTarget& target, const std::string& s, Vec2 at, double size,
                 sf::Color colour, const PixelRect& room, Align align = Align::Left,
                 bool bold = false);
  /// How wide a line of regular text is at a size (px).
  double widthOf(const std::string& s, double size) const;
  void drawPlayers(sf::RenderTarget& target, const ViewTransform& view, const HudState& hud,
                   const HudLayout& layout);
  void drawBottom(sf::RenderTarget& target, const HudState& hud, const HudLayout& layout);
  void drawOverlay(sf::RenderTarget& target, const HudState& hud, const HudLayout& layout);
  /// One ball's icon, its number (two digits too) fitted inside its number disc.
  void drawBallIcon(sf::RenderTarget& target, int id, Vec2 centre, double r);
  void drawTray(sf::RenderTarget& target, const HudState& hud, const PixelRect& room, double r);

  const Fonts& fonts_;
  BallPainter balls_;
  BallLooks looks_ = poolBallLook;
  TriangleBatch batch_;
  std::vector<DrawnText> drawn_;
};

}  // namespace nineball::render
