#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>
#include <map>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/colours.hpp"
#include "render/triangle_batch.hpp"
#include "render/view_transform.hpp"

namespace nineball::render {

/// Balls seen from above: shadow, standard colour (stripe for 9 and up), the white disc with
/// the number, a highlight.
class BallPainter {
 public:
  explicit BallPainter(const sf::Font& numbers) : font_(numbers) {}
  /// The set of balls drawn (a game's looks; pool balls until told).
  void setLooks(BallLooks looks) { looks_ = looks; }

  /// Draws every ball still on the table at its given position, radius r metres.
  void draw(sf::RenderTarget& target, const ViewTransform& view,
            const std::vector<BallState>& balls, double r);
  /// One ball at a pixel position and pixel radius (the HUD's icons); `alpha` fades it.
  void drawOne(sf::RenderTarget& target, int id, Vec2 centre_px, double radius_px,
               std::uint8_t alpha = 255);

 private:
  void addBall(int id, Vec2 c, double r, std::uint8_t alpha);
  sf::Text& number(int id, unsigned size);

  const sf::Font& font_;
  BallLooks looks_ = poolBallLook;
  TriangleBatch shadows_;
  TriangleBatch bodies_;
  std::map<int, sf::Text> numbers_;
};

}  // namespace nineball::render
