#include "physics/model/contact_times.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>

#include "physics/model/polynomial.hpp"
#include "physics/resolve/ball_ball/collide.hpp"

namespace nineball::physics {
namespace {

// |p(s) - q(s)|^2 - distance^2 for relative position d, velocity e and acceleration g.
Quartic separation(Vec2 d, Vec2 e, Vec2 g, double distance) {
  return {{dot(d, d) - distance * distance, 2.0 * dot(d, e), dot(e, e) + dot(d, g), dot(e, g),
           0.25 * dot(g, g)}};
}

// True when a relative path d + e s + g s^2 / 2 runs along a straight line (e and g parallel,
// as for two rolling balls, or a rolling ball and a point) that passes further than `distance`
// from the origin: then it never comes that close. The margin (1e-9 relative, and the line's
// straightness to 1e-12) is far above the rounding of the test.
bool lineMisses(Vec2 d, Vec2 e, Vec2 g, double distance) {
  const double ee = dot(e, e), gg = dot(g, g);
  const Vec2 dir = ee >= gg ? e : g;
  const double dd = ee >= gg ? ee : gg;
  if (!(dd > 0.0)) return false;
  const double bend = cross(e, g);
  if (bend * bend > 1e-24 * ee * gg) return false;
  const double off = cross(d, dir);  // |d| |dir| sin: the line's distance from 0, times |dir|
  const double reach = distance + kTouchTolerance;
  return off * off > reach * reach * dd * (1.0 + 1e-9) + 1e-18 * dot(d, d) * dd;
}

// Two circles `distance` apart at their closest: first touch while closing. With
// `pressed_apart`, circles resting against each other are met again once pressed a touch
// tolerance together, for the contact to set them back to touching.
std::optional<double> meet(Vec2 d, Vec2 e, Vec2 g, double distance, double horizon,
                           bool pressed_apart) {
  // Most pairs are far apart: answered from squares, without the three hypot calls below. The
  // margin (1e-9 relative) dwarfs sqrt's rounding against hypot's, so this only answers
  // "never" where the exact test below would: the results stay bit for bit the same.
  const double far = distance + kTouchTolerance + std::sqrt(dot(e, e)) * horizon +
                     0.5 * std::sqrt(dot(g, g)) * horizon * horizon;
  if (dot(d, d) > far * far * (1.0 + 1e-9)) return std::nullopt;
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
  if (lineMisses(d, e, g, distance)) return std::nullopt;
  return firstCrossing(separation(d, e, g, distance), 0.0, horizon);
}

// A jaw point (a corner of the cushion loop). Within the touch tolerance but not on it, a ball
// closing on it is met where its path reaches it, not at once: one rolling along a rail past
// the rail's end only passes the point by, and would otherwise be met with the closing speed
// the tolerance gives it (up to v sqrt(2 tol / R), a few mm/s), in one engine and not the
// other depending on when the search ran.
std::optional<double> cornerContact(Vec2 d, const Path& path, double gap, double radius,
                                    double horizon) {
  if (gap > 0.0 && gap <= kTouchTolerance && -dot(d, path.v) > kMinClosingSpeed * length(d)) {
    const Quartic q = separation(d, path.v, path.a, radius);
    if (!(q(0.0) > 0.0)) return 0.0;
    return firstCrossing(q, 0.0, horizon);
  }
  return meet(d, path.v, path.a, radius, horizon, true);
}

// A ball behind a cushion line (gap < 0) whose path bends back: it comes out in front while
// moving away from the line (vn > 0, an < 0), turns at s = -vn / an, and meets the line again
// from the table's side at the first root past that turn, if it got out of touch in between.
std::optional<double> backFromBehind(double gap, double vn, double an, double horizon) {
  if (!(vn > 0.0 && an < 0.0)) return std::nullopt;
  const double turn = -vn / an;
  if (!(turn < horizon)) return std::nullopt;
  const Quartic height{{gap, vn, 0.5 * an, 0.0, 0.0}};
  if (!(height(turn) > kTouchTolerance)) return std::nullopt;
  return firstCrossing(height, turn, horizon);
}

}  // namespace

Cushions Cushions::of(const TableGeometry& table) {
  Cushions c;
  const auto& loop = table.cushion_loop;
  const std::size_t n = loop.size();
  // The chords that stand for a knuckle in the loop (and the vertices between and at their
  // ends, where the knuckle meets its straight pieces tangentially) give way to its arc.
  std::vector<bool> in_arc(n, false), on_arc(n, false);
  for (const CushionArc& arc : table.arcs) {
    for (std::size_t k = arc.first; k <= arc.last; ++k) {
      on_arc[k] = true;
      if (k < arc.last) in_arc[k] = true;
    }
    c.arcs.push_back({arc.centre, arc.radius, normalized(arc.start - arc.centre),
                      normalized(arc.end - arc.centre)});
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = loop[i], b = loop[(i + 1) % n];
    const double len = length(b - a);
    if (len <= 0.0 || in_arc[i]) continue;
    const Vec2 along = (b - a) / len;
    // The loop runs clockwise: the table is on the right of each segment.
    c.segments.push_back({a, b, along, {along.y, -along.x}, len});
    // A left turn at b (walking clockwise) points b into the table.
    const Vec2 next = loop[(i + 2) % n];
    if (cross(b - a, next - b) > 0.0 && !on_arc[(i + 1) % n]) c.corners.push_back(b);
  }
  c.buildGrid();
  return c;
}

std::shared_ptr<const Cushions> Cushions::sharedOf(const TableGeometry& table) {
  constexpr std::size_t kKept = 8;
  static std::mutex mutex;
  static std::deque<std::pair<std::vector<Vec2>, std::shared_ptr<const Cushions>>> kept;
  const std::lock_guard<std::mutex> lock(mutex);
  for (const auto& [loop, cushions] : kept) {
    if (loop == table.cushion_loop) return cushions;
  }
  auto built = std::make_shared<const Cushions>(of(table));
  kept.emplace_front(table.cushion_loop, built);
  if (kept.size() > kKept) kept.pop_back();
  return built;
}

void Cushions::buildGrid() {
  if (segments.empty()) return;
  Vec2 lo = segments.front().a, hi = lo;
  for (const Segment& seg : segments) {
    for (Vec2 q : {seg.a, seg.b}) {
      lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
      hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
    }
  }
  grid_min = lo;
  grid_nx = static_cast<int>(std::ceil((hi.x - lo.x) / kGridCell)) + 1;
  grid_ny = static_cast<int>(std::ceil((hi.y - lo.y) / kGridCell)) + 1;
  std::vector<std::vector<int>> cells(static_cast<std::size_t>(grid_nx * grid_ny));
  // The cells along one axis that a span from `from` to `to`, grown by kGridReach, covers.
  auto cells_along = [](double from, double to, double origin, int count) {
    const auto at = [&](double x) {
      return static_cast<int>(std::floor((x - origin) / kGridCell));
    };
    return std::make_pair(std::max(0, at(from - kGridReach)),
                          std::min(count - 1, at(to + kGridReach)));
  };
  auto add = [&](int item, Vec2 a, Vec2 b) {
    const auto [x0, x1] = cells_along(std::min(a.x, b.x), std::max(a.x, b.x), lo.x, grid_nx);
    const auto [y0, y1] = cells_along(std::min(a.y, b.y), std::max(a.y, b.y), lo.y, grid_ny);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x)
        cells[static_cast<std::size_t>(y * grid_nx + x)].push_back(item);
    }
  };
  int item = 0;
  for (const Segment& seg : segments) add(item++, seg.a, seg.b);
  for (Vec2 corner : corners) add(item++, corner, corner);
  for (const Arc& arc : arcs) {
    const Vec2 reach{arc.radius, arc.radius};
    add(item++, arc.centre - reach, arc.centre + reach);
  }
  cell_start.assign(1, 0);
  for (const auto& cell : cells) {
    items.insert(items.end(), cell.begin(), cell.end());
    cell_start.push_back(static_cast<int>(items.size()));
  }
}

std::optional<int> Cushions::cellOf(Vec2 p) const {
  const double fx = std::floor((p.x - grid_min.x) / kGridCell);
  const double fy = std::floor((p.y - grid_min.y) / kGridCell);
  if (!(fx >= 0.0 && fy >= 0.0 && fx < grid_nx && fy < grid_ny)) return std::nullopt;
  return static_cast<int>(fy) * grid_nx + static_cast<int>(fx);
}

double reach(const Path& path, double horizon) {
  // Only ever a bound with a touch tolerance of room (1 um), far beyond sqrt's rounding against
  // hypot's: sqrt is several times cheaper and nothing it decides changes.
  return std::sqrt(dot(path.v, path.v)) * horizon +
         0.5 * std::sqrt(dot(path.a, path.a)) * horizon * horizon;
}

std::optional<double> ballContact(const Path& a, const Path& b, double distance, double horizon) {
  return meet(b.p - a.p, b.v - a.v, b.a - a.a, distance, horizon, true);
}

std::optional<double> ballContactInAir(const Path& a, Height za, const Path& b, Height zb,
                                       double distance, double horizon) {
  const Vec2 d = b.p - a.p, e = b.v - a.v, g = b.a - a.a;
  const double z0 = zb.z0 - za.z0, z1 = zb.vz - za.vz, z2 = 0.5 * (zb.accel - za.accel);
  // |d + e s + g s^2 / 2|^2 + (z0 + z1 s + z2 s^2)^2 - distance^2, a quartic in s.
  const Quartic f{{dot(d, d) + z0 * z0 - distance * distance, 2.0 * (dot(d, e) + z0 * z1),
                   dot(e, e) + dot(d, g) + z1 * z1 + 2.0 * z0 * z2, dot(e, g) + 2.0 * z1 * z2,
                   0.25 * dot(g, g) + z2 * z2}};
  const double apart = std::sqrt(dot(d, d) + z0 * z0);
  if (apart - distance <= kTouchTolerance) {
    const double closing = apart > 0.0 ? -(dot(d, e) + z0 * z1) / apart : 0.0;
    if (closing > kMinClosingSpeed) return 0.0;
    // Parting, but gravity may bring them back (a ball bouncing on another): the distance's
    // square is back at today's at the first root of (f(s) - f(0)) / s.
    if (-closing <= kMinClosingSpeed) return std::nullopt;
    return firstCrossing(Quartic{{f.c[1], f.c[2], f.c[3], f.c[4], 0.0}}, 0.0, horizon);
  }
  return firstCrossing(f, 0.0, horizon);
}

std::optional<CushionHit> cushionContact(const Path& path, double radius, const Cushions& cushions,
                                         double horizon) {
  std::optional<CushionHit> best;
  const double limit = reach(path, horizon) + radius + kTouchTolerance;
  // Whatever the ball touches lies within a radius of its path (the slack covers rounding).
  const Box near = boxOf(path, horizon).grown(radius + 2.0 * kTouchTolerance);
  auto consider = [&](double s, Vec2 normal) {
    if (!best || s < best->s) best = CushionHit{s, normal};
  };
  auto segment = [&](const Cushions::Segment& seg) {
    const double height = dot(path.p - seg.a, seg.inward);
    const double foot = dot(path.p - seg.a, seg.along);
    if (height > limit || foot < -limit || foot > seg.length + limit) return;
    const Box extent{std::min(seg.a.x, seg.b.x), std::max(seg.a.x, seg.b.x),
                     std::min(seg.a.y, seg.b.y), std::max(seg.a.y, seg.b.y)};
    if (!near.overlaps(extent)) return;
    const double gap = height - radius;
    const double vn = dot(path.v, seg.inward);
    const double an = dot(path.a, seg.inward);
    std::optional<double> s;
    if (gap < -kTouchTolerance) {
      // Behind this segment's line. On it, the ball has sunk past the tolerance (pressed by
      // others) and is met at once to be set out again, unless it is leaving. Off its ends (or
      // leaving) another segment holds it now, but a curved path (sliding, swerve) may bring
      // it out in front of this line and back onto the segment later.
      const bool on_it = gap >= -radius && foot >= 0.0 && foot <= seg.length;
      s = on_it && vn <= kMinClosingSpeed ? std::optional<double>(0.0)
                                          : backFromBehind(gap, vn, an, horizon);
    } else if (gap <= kTouchTolerance) {  // touching, or pressed a little into it
      if (vn < -kMinClosingSpeed) {
        s = 0.0;
      } else if (vn > kMinClosingSpeed) {
        // Leaving the cushion, perhaps to be pulled back by spin: back on it when the height
        // gained, s (vn + a_n s / 2), is zero again.
        s = firstCrossing(Quartic{{vn, 0.5 * an, 0.0, 0.0, 0.0}}, 0.0, horizon);
      } else {
        // Resting on it: met again if pressed a touch tolerance in.
        s = firstCrossing(Quartic{{gap + kTouchTolerance, vn, 0.5 * an, 0.0, 0.0}}, 0.0, horizon);
      }
    } else {
      s = firstCrossing(Quartic{{gap, vn, 0.5 * an, 0.0, 0.0}}, 0.0, horizon);
    }
    if (!s) return;
    const double at = dot(path.at(*s) - seg.a, seg.along);
    if (at >= 0.0 && at <= seg.length) consider(*s, seg.inward);
  };
  auto corner = [&](Vec2 c) {
    const Vec2 d = path.p - c;
    if (!near.overlaps({c.x, c.x, c.y, c.y})) return;
    const double distance = length(d);
    if (distance > limit) return;
    if (auto s = cornerContact(d, path, distance - radius, radius, horizon)) {
      consider(*s, normalized(path.at(*s) - c));
    }
  };
  auto arc = [&](const Cushions::Arc& k) {
    const Vec2 d = path.p - k.centre;
    if (!near.overlaps(Box{k.centre.x, k.centre.x, k.centre.y, k.centre.y}.grown(k.radius))) return;
    const double distance = length(d);
    if (distance - k.radius > limit) return;
    // As a corner met at R + rho, kept when the meeting point lies within the arc's span:
    // outside it, the nose or jaw face the arc runs into tangentially is met instead.
    const double reach_to_centre = radius + k.radius;
    if (auto s = cornerContact(d, path, distance - reach_to_centre, reach_to_centre, horizon)) {
      const Vec2 normal = normalized(path.at(*s) - k.centre);
      if (k.covers(normal)) consider(*s, normal);
    }
  };
  // Every segment, corner or arc a hit can come from lies within `limit` of the start (the
  // ball touches it within its reach), so the start's cell lists all of them, in the same order.
  const int n = static_cast<int>(cushions.segments.size());
  const int corner_end = n + static_cast<int>(cushions.corners.size());
  const auto cell = limit <= Cushions::kGridReach ? cushions.cellOf(path.p) : std::nullopt;
  if (cell) {
    const auto c = static_cast<std::size_t>(*cell);
    for (int k = cushions.cell_start[c]; k < cushions.cell_start[c + 1]; ++k) {
      const int item = cushions.items[static_cast<std::size_t>(k)];
      if (item < n) {
        segment(cushions.segments[static_cast<std::size_t>(item)]);
      } else if (item < corner_end) {
        corner(cushions.corners[static_cast<std::size_t>(item - n)]);
      } else {
        arc(cushions.arcs[static_cast<std::size_t>(item - corner_end)]);
      }
    }
    return best;
  }
  for (const Cushions::Segment& seg : cushions.segments) segment(seg);
  for (Vec2 c : cushions.corners) corner(c);
  for (const Cushions::Arc& k : cushions.arcs) arc(k);
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
  for (const Cushions::Arc& arc : cushions.arcs) {
    const Vec2 d = p - arc.centre;
    const double distance = length(d);
    if (distance - arc.radius - radius <= kTouchTolerance && distance >= arc.radius &&
        arc.covers(d)) {
      normals.push_back(d / distance);
    }
  }
  return normals;
}

std::optional<double> circleEntry(const Path& path, Vec2 centre, double radius, double horizon) {
  const Vec2 d = path.p - centre;
  if (dot(d, d) <= radius * radius) return 0.0;
  const Box circle = Box{centre.x, centre.x, centre.y, centre.y}.grown(radius + kTouchTolerance);
  if (!boxOf(path, horizon).overlaps(circle)) return std::nullopt;
  if (length(d) - radius > reach(path, horizon) + kTouchTolerance) return std::nullopt;
  if (lineMisses(d, path.v, path.a, radius)) return std::nullopt;
  return firstCrossing(separation(d, path.v, path.a, radius), 0.0, horizon);
}

}  // namespace nineball::physics
