#include "physics/ball_collision.hpp"

#include <cmath>

namespace nineball::physics {

CollisionOutcome collide(Vec2 u1, Vec2 u2, double m1, double m2, double e, Vec2 n) {
  const double u1n = dot(u1, n), u2n = dot(u2, n);
  const double total = m1 + m2;
  const double v1n = (m1 * u1n + m2 * u2n + m2 * e * (u2n - u1n)) / total;
  const double v2n = (m1 * u1n + m2 * u2n + m1 * e * (u1n - u2n)) / total;
  return {u1 + n * (v1n - u1n), u2 + n * (v2n - u2n)};
}

std::optional<double> contactFraction(Vec2 rel, Vec2 rel_move, double contact_distance, double from,
                                      bool closing) {
  const Vec2 start = rel + rel_move * from;
  const double c = dot(start, start) - contact_distance * contact_distance;
  const double touching = 2.0 * contact_distance * kTouchTolerance;
  if (c <= touching) {
    if (closing) return from;
    return std::nullopt;
  }
  const double b = dot(start, rel_move);
  if (b >= 0.0) return std::nullopt;  // moving apart over the rest of the step
  const double a = dot(rel_move, rel_move);
  const double disc = b * b - a * c;
  if (disc < 0.0) return std::nullopt;
  // (-b - sqrt(disc)) / a, written to keep precision when the root is small.
  const double sigma = c / (-b + std::sqrt(disc));
  const double s = from + sigma;
  if (s > 1.0) return std::nullopt;
  return s;
}

}  // namespace nineball::physics
