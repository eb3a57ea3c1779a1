#include "render/guide_foul_painter.hpp"

#include <SFML/Graphics/Text.hpp>
#include <algorithm>
#include <cmath>

#include "render/triangle_batch.hpp"

namespace nineball::render {
namespace {

const sf::Color kFoulLine(235, 60, 50, 230);
const sf::Color kFoulText(255, 150, 130);
const sf::Color kLabelBox(10, 12, 14, 210);

}  // namespace

void drawGuideFoulPath(sf::RenderTarget& target, const ViewTransform& view, const AimGuide& guide,
                       double ball_radius) {
  const double w = std::max(2.0, view.px(0.005));
  const double r = view.px(ball_radius);
  const Vec2 ghost = view.toPixels(guide.end);
  TriangleBatch marks;
  marks.softLine(view.toPixels(guide.start), ghost, w, kFoulLine);
  marks.softRing(ghost, r - w, r, kFoulLine);
  marks.draw(target);
}

void drawGuideFoulLabel(sf::RenderTarget& target, const ViewTransform& view, const AimGuide& guide,
                        double ball_radius, const std::string& why, const Fonts& fonts) {
  const double r = view.px(ball_radius);
  const Vec2 ghost = view.toPixels(guide.end);
  sf::Text label(why, fonts.regular, static_cast<unsigned>(std::max(10.0, r * 1.1)));
  label.setFillColor(kFoulText);
  const sf::FloatRect b = label.getLocalBounds();
  // Beside the ghost ball, on whichever side has room.
  double x = ghost.x + r * 1.6;
  if (x + b.width + r > view.widthPx()) x = ghost.x - r * 1.6 - b.width;
  const double y = ghost.y + r * 1.2;
  label.setPosition(std::round(static_cast<float>(x)), std::round(static_cast<float>(y)));
  TriangleBatch box;
  box.roundedRect(x - r * 0.4, y - r * 0.1, b.width + r * 0.8, b.top + b.height + r * 0.5, r * 0.4,
                  kLabelBox);
  box.draw(target);
  target.draw(label);
}

}  // namespace nineball::render
