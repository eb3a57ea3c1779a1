#include "render/ball_painter.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::render {

namespace {

// How much larger a ball in the air is drawn: as seen from a little above, the nearer the
// larger (exaggerated, so that a hop of a few centimetres is seen).
double airScale(double z) {
  return 1.0 + std::clamp(z, 0.0, 0.3) / 0.15;
}

}  // namespace

void BallPainter::shadow(Vec2 c, double r, std::uint8_t alpha, double lift_px) {
  // Away from the light (up and to the top left): down and to the right on screen, soft; the
  // higher the ball, the further its shadow falls.
  const Vec2 at = c + Vec2{0.16 * r + 0.6 * lift_px, 0.22 * r + 0.8 * lift_px};
  const int segments = circleSegments(r) + 8;
  shadows_.circle(at, r * 1.08, sf::Color(0, 0, 0, static_cast<std::uint8_t>(alpha / 7)), segments);
  shadows_.circle(at, r * 0.98, sf::Color(0, 0, 0, static_cast<std::uint8_t>(alpha / 5)), segments);
}

void BallPainter::sinking(sf::RenderTarget& target, const ViewTransform& view, const BallState& b,
                          double r, double time, const TableGeometry& table) {
  const BallSpins::Drop* drop = spins_.dropOf(b.id);
  if (!drop || !b.pocket) return;
  const double p = (time - drop->time) / kSinkTime;
  if (!(p >= 0.0 && p < 1.0)) return;
  Vec2 centre = drop->at;
  for (const Pocket& pk : table.pockets) {
    if (pk.id == *b.pocket) centre = pk.drop_centre;
  }
  // Off the table over a rail: it goes on outwards, fading, no pocket below it.
  if (b.off_table) centre = drop->at + normalized(drop->at) * (3.0 * r);
  // Eased: it rolls over the edge quickly, then settles into the dark.
  const double e = 1.0 - (1.0 - p) * (1.0 - p);
  SphereBallRenderer::Ball ball;
  ball.look = looks_(b.id);
  ball.number = b.id;
  ball.q = spins_.of(b.id);
  ball.centre_px = view.toPixels(drop->at + (centre - drop->at) * e);
  ball.radius_px = view.px(r) * (1.0 - 0.3 * e);
  ball.darken = 0.85 * e;
  ball.alpha = static_cast<std::uint8_t>(std::lround(255.0 * std::min(1.0, 4.0 * (1.0 - p))));
  spheres_.draw(target, ball);
}

void BallPainter::draw(sf::RenderTarget& target, const ViewTransform& view,
                       const std::vector<BallState>& balls, double r, double time,
                       const TableGeometry& table) {
  spins_.advance(balls, time);
  for (const BallState& b : balls) sinking(target, view, b, r, time, table);
  shadows_.clear();
  const double r_px = view.px(r);
  for (const BallState& b : balls) {
    // A ball in the air casts a fainter shadow on the cloth, further from it.
    const double fade = 1.0 - std::clamp(b.z / 0.3, 0.0, 0.6);
    if (!b.pocket) {
      shadow(view.toPixels(b.pos), r_px, static_cast<std::uint8_t>(255.0 * fade), view.px(b.z));
    }
  }
  shadows_.draw(target);
  // The balls on the cloth first, then those in the air, lowest first: a ball flying over
  // another is drawn over it.
  std::vector<const BallState*> order;
  for (const BallState& b : balls) {
    if (!b.pocket) order.push_back(&b);
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const BallState* a, const BallState* b) { return a->z < b->z; });
  for (const BallState* b : order) {
    SphereBallRenderer::Ball ball;
    ball.look = looks_(b->id);
    ball.number = b->id;
    ball.q = spins_.of(b->id);
    ball.centre_px = view.toPixels(b->pos);
    ball.radius_px = r_px * airScale(b->z);
    spheres_.draw(target, ball);
  }
}

void BallPainter::drawOne(sf::RenderTarget& target, int id, Vec2 centre_px, double radius_px,
                          std::uint8_t alpha) {
  SphereBallRenderer::Ball ball;
  ball.look = looks_(id);
  ball.number = id;
  ball.centre_px = centre_px;
  ball.radius_px = radius_px;
  ball.alpha = alpha;
  spheres_.draw(target, ball);
}

}  // namespace nineball::render
