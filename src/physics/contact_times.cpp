#include "physics/contact_times.hpp"

#include <algorithm>
#include <cmath>

#include "physics/ball_collision.hpp"
#include "physics/polynomial.hpp"

namespace nineball::physics {
namespace {

// |p(s) - q(s)|^2 - distance^2 for relative position d, velocity e and acceleration g.
Quartic separation(Vec2 d, Vec2 e, Vec2 g, double distance) {
  return {{dot(d, d) - distance * distance, 2.0 * dot(d, e), dot(e, e) + dot(d, g), dot(e, g),
           0.25 * dot(g, g)}};
}

// Two circles `distance` apart at their closest: first touch while closing. With
// `pressed_apart`, circles resting against each other are met again once pressed a touch
// tolerance together, for the contact to set them back to touching.
std::optional<double> meet(Vec2 d, Vec2 e, Vec2 g, double distance, double horizon,
                           bool pressed_apart) {
  const double gap = length(d) - distance;
  if (gap <= kTouchTolerance) {
    const double closing = -dot(normalized(d), e);
    if (closing > kMinClosingSpeed) return 0.0;
    if (pressed_apart && -closing <= kMinClosingSpeed) {
      if (gap < -kTouchTolerance) return 0.0;
      return firstCrossing(separation(d, e, g, distance - kTouchTolerance), 0.0, horizon);
    }
    // Parting, but spin or the cloth may bring them back: |d(s)|^2 - |d(0)|^2 = s c(s), so
    // they are back at today's distance at the first root of c. Slower parting is a resting
    // contact: chasing it would be an endless run of ever smaller bounces.
    if (-closing <= kMinClosingSpeed) return std::nullopt;
    return firstCrossing(
        Quartic{{2.0 * dot(d, e), dot(e, e) + dot(d, g), dot(e, g), 0.25 * dot(g, g), 0.0}}, 0.0,
        horizon);
  }
  if (gap > length(e) * horizon + 0.5 * length(g) * horizon * horizon) return std::nullopt;
  return firstCrossing(separation(d, e, g, distance), 0.0, horizon);
}

}  // namespace

Cushions Cushions::of(const TableGeometry& table) {
  Cushions c;
  const auto& loop = table.cushion_loop;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = loop[i], b = loop[(i + 1) % n];
    const double len = length(b - a);
    if (len <= 0.0) continue;
    const Vec2 along = (b - a) / len;
    // The loop runs clockwise: the table is on the right of each segment.
    c.segments.push_back({a, b, along, {along.y, -along.x}, len});
    // A left turn at b (walking clockwise) points b into the table.
    const Vec2 next = loop[(i + 2) % n];
    if (cross(b - a, next - b) > 0.0) c.corners.push_back(b);
  }
  return c;
}

double reach(const Path& path, double horizon) {
  return length(path.v) * horizon + 0.5 * length(path.a) * horizon * horizon;
}

std::optional<double> ballContact(const Path& a, const Path& b, double distance, double horizon) {
  return meet(b.p - a.p, b.v - a.v, b.a - a.a, distance, horizon, true);
}

std::optional<CushionHit> cushionContact(const Path& path, double radius, const Cushions& cushions,
                                         double horizon) {
  std::optional<CushionHit> best;
  const double limit = reach(path, horizon) + radius + kTouchTolerance;
  auto consider = [&](double s, Vec2 normal) {
    if (!best || s < best->s) best = CushionHit{s, normal};
  };
  for (const Cushions::Segment& seg : cushions.segments) {
    const double height = dot(path.p - seg.a, seg.inward);
    const double foot = dot(path.p - seg.a, seg.along);
    if (height > limit || foot < -limit || foot > seg.length + limit) continue;
    const double gap = height - radius;
    const double vn = dot(path.v, seg.inward);
    std::optional<double> s;
    if (gap < -kTouchTolerance) {
      // Behind this segment's line. Off its ends another segment holds the ball; on it, the
      // ball has sunk past the tolerance (pressed by others) and is met to be set out again:
      // at once if it still goes in, else once pressed further, unless it is leaving.
      if (gap < -radius || foot < 0.0 || foot > seg.length || vn > kMinClosingSpeed) continue;
      s = 0.0;
    } else if (gap <= kTouchTolerance) {  // touching, or pressed a little into it
      if (vn < -kMinClosingSpeed) {
        s = 0.0;
      } else if (vn > kMinClosingSpeed) {
        // Leaving the cushion, perhaps to be pulled back by spin: back on it when the height
        // gained, s (vn + a_n s / 2), is zero again.
        s = firstCrossing(Quartic{{vn, 0.5 * dot(path.a, seg.inward), 0.0, 0.0, 0.0}}, 0.0,
                          horizon);
      } else {
        // Resting on it: met again if pressed a touch tolerance in.
        s = firstCrossing(
            Quartic{{gap + kTouchTolerance, vn, 0.5 * dot(path.a, seg.inward), 0.0, 0.0}}, 0.0,
            horizon);
      }
    } else {
      s = firstCrossing(Quartic{{gap, vn, 0.5 * dot(path.a, seg.inward), 0.0, 0.0}}, 0.0, horizon);
    }
    if (!s) continue;
    const double at = dot(path.at(*s) - seg.a, seg.along);
    if (at >= 0.0 && at <= seg.length) consider(*s, seg.inward);
  }
  for (Vec2 corner : cushions.corners) {
    const Vec2 d = path.p - corner;
    if (length(d) > limit) continue;
    if (auto s = meet(d, path.v, path.a, radius, horizon, true)) {
      consider(*s, normalized(path.at(*s) - corner));
    }
  }
  return best;
}

std::vector<Vec2> touchingNormals(Vec2 p, double radius, const Cushions& cushions) {
  std::vector<Vec2> normals;
  for (const Cushions::Segment& seg : cushions.segments) {
    const double gap = dot(p - seg.a, seg.inward) - radius;
    const double foot = dot(p - seg.a, seg.along);
    if (gap <= kTouchTolerance && gap >= -radius && foot >= 0.0 && foot <= seg.length) {
      normals.push_back(seg.inward);
    }
  }
  for (Vec2 corner : cushions.corners) {
    if (length(p - corner) - radius <= kTouchTolerance) normals.push_back(normalized(p - corner));
  }
  return normals;
}

std::optional<double> circleEntry(const Path& path, Vec2 centre, double radius, double horizon) {
  const Vec2 d = path.p - centre;
  if (dot(d, d) <= radius * radius) return 0.0;
  if (length(d) - radius > reach(path, horizon)) return std::nullopt;
  return firstCrossing(separation(d, path.v, path.a, radius), 0.0, horizon);
}

}  // namespace nineball::physics
