#include "render/ball_painter.hpp"

#include <cmath>
#include <string>

#include "render/palette.hpp"

namespace nineball::render {
namespace {

constexpr Rgb kOutline{10, 10, 10};
constexpr Rgb kNumberInk{20, 20, 20};

// The stripe: the part of the circle within kStripeHalfHeight of its horizontal diameter.
std::vector<Vec2> stripeOutline(Vec2 c, double r) {
  const double a = std::asin(kStripeHalfHeight);
  constexpr int kArc = 10;
  std::vector<Vec2> pts;
  for (int side = 0; side < 2; ++side) {
    const double base = side == 0 ? 0.0 : kPi;
    for (int i = 0; i <= kArc; ++i) {
      pts.push_back(c + fromAngle(base - a + 2.0 * a * i / kArc) * r);
    }
  }
  return pts;
}

}  // namespace

sf::Text& BallPainter::number(int id, unsigned size) {
  auto it = numbers_.find(id);
  if (it == numbers_.end()) {
    it = numbers_.emplace(id, sf::Text(std::to_string(id), font_, size)).first;
    it->second.setFillColor(toSf(kNumberInk));
  }
  sf::Text& t = it->second;
  if (t.getCharacterSize() != size) t.setCharacterSize(size);
  const sf::FloatRect b = t.getLocalBounds();
  t.setOrigin(b.left + b.width / 2.0f, b.top + b.height / 2.0f);
  return t;
}

void BallPainter::addBall(int id, Vec2 c, double r, std::uint8_t alpha) {
  const int segments = circleSegments(r) + 8;
  shadows_.circle(c + Vec2{0.14 * r, 0.2 * r}, r * 1.02, sf::Color(0, 0, 0, alpha / 4), segments);
  bodies_.circle(c, r + 0.8, toSf(kOutline, alpha / 2), segments);
  const BallLook look = looks_(id);
  if (look.stripe) {
    bodies_.circle(c, r, toSf(kNumberDisc, alpha), segments);
    bodies_.convex(stripeOutline(c, r), toSf(look.colour, alpha));
  } else {
    bodies_.circle(c, r, toSf(look.colour, alpha), segments);
  }
  if (look.numbered) bodies_.circle(c, r * kNumberDiscRadius, toSf(kNumberDisc, alpha));
  bodies_.circle(c + Vec2{-0.38 * r, -0.42 * r}, 0.18 * r, sf::Color(255, 255, 255, alpha / 2));
}

void BallPainter::draw(sf::RenderTarget& target, const ViewTransform& view,
                       const std::vector<BallState>& balls, double r) {
  shadows_.clear();
  bodies_.clear();
  const double r_px = view.px(r);
  for (const BallState& b : balls) {
    if (!b.pocket) addBall(b.id, view.toPixels(b.pos), r_px, 255);
  }
  shadows_.draw(target);
  bodies_.draw(target);
  const unsigned size = static_cast<unsigned>(std::max(6.0, std::round(r_px * 0.85)));
  for (const BallState& b : balls) {
    if (b.pocket || !looks_(b.id).numbered) continue;
    sf::Text& t = number(b.id, size);
    t.setPosition(toSf(view.toPixels(b.pos)));
    target.draw(t);
  }
}

void BallPainter::drawOne(sf::RenderTarget& target, int id, Vec2 centre_px, double radius_px,
                          std::uint8_t alpha) {
  shadows_.clear();
  bodies_.clear();
  addBall(id, centre_px, radius_px, alpha);
  bodies_.draw(target);
  if (!looks_(id).numbered) return;
  sf::Text& t = number(id, static_cast<unsigned>(std::max(6.0, std::round(radius_px * 0.85))));
  t.setPosition(toSf(centre_px));
  t.setFillColor(toSf(kNumberInk, alpha));
  target.draw(t);
  t.setFillColor(toSf(kNumberInk));
}

}  // namespace nineball::render
