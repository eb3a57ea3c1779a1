#include "physics/resolve/ball_ball/collide.hpp"

#include <cmath>

namespace nineball::physics {

CollisionOutcome collide(Vec2 u1, Vec2 u2, double m1, double m2, double e, Vec2 n) {
  const double u1n = dot(u1, n), u2n = dot(u2, n);
  const double total = m1 + m2;
  const double v1n = (m1 * u1n + m2 * u2n + m2 * e * (u2n - u1n)) / total;
  const double v2n = (m1 * u1n + m2 * u2n + m1 * e * (u1n - u2n)) / total;
  return {u1 + n * (v1n - u1n), u2 + n * (v2n - u2n)};
}

}  // namespace nineball::physics
