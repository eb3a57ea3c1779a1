#include "play/aim_guide.hpp"

#include <cmath>
#include <limits>

namespace nineball {
namespace {

// A path that starts touching a surface (a ball frozen to a cushion, within the rounding that
// TableGeometry::ballFits allows) still hits it.
constexpr double kStartTolerance = 1e-6;

// First t >= 0 at which p + t d (|d| = 1) enters the circle (c, r); 0 when it starts touching
// and moves closer; nothing when it misses or moves away.
std::optional<double> rayEntersCircle(Vec2 p, Vec2 d, Vec2 c, double r) {
  const Vec2 m = p - c;
  const double b = dot(m, d);
  const double cc = dot(m, m) - r * r;
  if (b >= 0.0) return std::nullopt;
  if (cc <= 0.0) return 0.0;
  const double disc = b * b - cc;
  if (disc < 0.0) return std::nullopt;
  return -b - std::sqrt(disc);
}

struct Hit {
  double t = std::numeric_limits<double>::infinity();
  Vec2 normal;
};

// The capsule of radius r round segment ab: its two sides and its two round ends.
void rayAgainstCapsule(Vec2 p, Vec2 d, Vec2 a, Vec2 b, double r, Hit& best) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  if (len2 > 0.0) {
    const Vec2 n = perp(normalized(ab));
    for (double side : {1.0, -1.0}) {
      const Vec2 face_normal = n * side;
      const double approach = dot(d, face_normal);
      if (approach >= 0.0) continue;
      const double t = dot(a + face_normal * r - p, face_normal) / approach;
      if (t < -kStartTolerance || t >= best.t) continue;
      const Vec2 h = p + d * t;
      const double u = dot(h - a, ab);
      if (u < 0.0 || u > len2) continue;
      best.t = std::max(t, 0.0);
      best.normal = face_normal;
    }
  }
  for (Vec2 end : {a, b}) {
    const auto t = rayEntersCircle(p, d, end, r);
    if (t && *t < best.t) {
      best.t = *t;
      best.normal = normalized(p + d * *t - end);
    }
  }
}

// The first thing a ball of radius r met going from `from` along the unit `d`: the cushion
// loop offset by r, the pockets' drop circles, other balls (circles of 2r; `skip_a` and
// `skip_b` are not in the way).
struct FirstHit {
  AimTarget target = AimTarget::Cushion;
  double t = 0.0;
  int ball = -1;
  Vec2 normal;
  std::optional<PocketId> pocket;
};

FirstHit firstHit(const TableGeometry& table, double r, const std::vector<BallState>& balls,
                  Vec2 from, Vec2 d, int skip_a, int skip_b) {
  FirstHit hit;
  Hit cushion;
  const std::size_t n = table.cushion_loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    rayAgainstCapsule(from, d, table.cushion_loop[i], table.cushion_loop[(i + 1) % n], r, cushion);
  }
  double best = cushion.t;
  hit.normal = cushion.normal;
  for (const Pocket& pocket : table.pockets) {
    const auto t = rayEntersCircle(from, d, pocket.drop_centre, pocket.drop_radius);
    if (t && *t < best) {
      best = *t;
      hit.target = AimTarget::Pocket;
      hit.pocket = pocket.id;
    }
  }
  for (const BallState& b : balls) {
    if (b.id == skip_a || b.id == skip_b || b.pocket) continue;
    const auto t = rayEntersCircle(from, d, b.pos, 2.0 * r);
    if (t && *t < best) {
      best = *t;
      hit.target = AimTarget::Ball;
      hit.ball = b.id;
      hit.pocket.reset();
    }
  }
  hit.t = std::isfinite(best) ? best : 0.0;  // a closed loop always stops the path
  if (hit.target != AimTarget::Cushion) hit.normal = {};
  return hit;
}

}  // namespace

AimGuide computeAimGuide(const TableGeometry& table, double ball_radius,
                         const std::vector<BallState>& balls, Vec2 cue, double heading_rad,
                         int cue_id) {
  const Vec2 d = fromAngle(heading_rad);
  const FirstHit first = firstHit(table, ball_radius, balls, cue, d, cue_id, cue_id);
  AimGuide guide;
  guide.start = cue;
  guide.end = cue + d * first.t;
  guide.target = first.target;
  guide.ball = first.ball;
  guide.cushion_normal = first.normal;
  guide.pocket = first.pocket;
  if (first.target != AimTarget::Ball) return guide;

  Vec2 object_pos;
  for (const BallState& b : balls) {
    if (b.id == first.ball) object_pos = b.pos;
  }
  guide.object_dir = normalized(object_pos - guide.end);
  const Vec2 tangent = d - guide.object_dir * dot(d, guide.object_dir);
  // Below this the hit is full: the stun cue ball has no tangent to follow.
  constexpr double kFullHit = 1e-9;
  guide.cue_dir = length(tangent) > kFullHit ? normalized(tangent) : Vec2{};
  guide.object_end =
      object_pos +
      guide.object_dir *
          firstHit(table, ball_radius, balls, object_pos, guide.object_dir, cue_id, first.ball).t;
  guide.cue_end = guide.end;
  if (guide.cue_dir != Vec2{}) {
    guide.cue_end =
        guide.end +
        guide.cue_dir *
            firstHit(table, ball_radius, balls, guide.end, guide.cue_dir, cue_id, first.ball).t;
  }
  return guide;
}

}  // namespace nineball
