#include "render/call_painter.hpp"

#include <SFML/Graphics/CircleShape.hpp>
#include <algorithm>

namespace nineball::render {
namespace {

void ring(sf::RenderTarget& target, Vec2 centre_px, double radius_px, double thick_px,
          bool filled) {
  const sf::Color colour(kCallRgb[0], kCallRgb[1], kCallRgb[2]);
  sf::CircleShape c(static_cast<float>(radius_px), 40);
  c.setOrigin(static_cast<float>(radius_px), static_cast<float>(radius_px));
  c.setPosition(static_cast<float>(centre_px.x), static_cast<float>(centre_px.y));
  c.setFillColor(filled ? colour : sf::Color::Transparent);
  c.setOutlineColor(colour);
  c.setOutlineThickness(static_cast<float>(thick_px));
  target.draw(c);
}

}  // namespace

void drawCall(sf::RenderTarget& target, const ViewTransform& view, const CallMark& call,
              double ball_radius) {
  const double r = view.px(ball_radius);
  const double thick = std::max(2.0, r * 0.18);
  if (call.ball) ring(target, view.toPixels(*call.ball), r + thick * 1.5, thick, false);
  if (call.pocket) {
    const Vec2 c = view.toPixels(*call.pocket);
    ring(target, c, r * 0.9, thick, false);
    ring(target, c, r * 0.35, 0.0, true);
  }
}

}  // namespace nineball::render
