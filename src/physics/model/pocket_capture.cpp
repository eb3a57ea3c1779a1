#include "physics/model/pocket_capture.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace nineball::physics {
namespace {

// Past the fall edge by this much (m) when set back on the table, so that the drop test does
// not find the ball entering the circle it is leaving.
constexpr double kOutside = 1e-9;

// The s > 0 at which the point p + v s leaves the circle of `radius` about the origin, moving
// out (the larger root of |p + v s| = radius), if it does.
std::optional<double> circleExit(Vec2 p, Vec2 v, double radius) {
  const double a = dot(v, v);
  if (a <= 0.0) return std::nullopt;
  const double b = dot(p, v);
  const double c = dot(p, p) - radius * radius;
  const double disc = b * b - a * c;
  if (disc < 0.0) return std::nullopt;
  // The larger root, without cancellation: (-b + sqrt) / a, or c / (-b - sqrt) when b > 0.
  const double root = std::sqrt(disc);
  const double s = b <= 0.0 ? (root - b) / a : -c / (b + root);
  if (!(s > 0.0)) return std::nullopt;
  return s;
}

// The ball, centre dropped z below the slate and falling at fall_speed, meets the slate's
// edge moving out along n. Pivoting on the edge it keeps its angular momentum about it; it
// comes back over when it has the energy to climb z. Its state on the cloth, or nothing.
std::optional<Kinematics> climbOut(const Kinematics& k, Vec2 n, double z, double fall_speed,
                                   const PhysicsParams& p) {
  const double r = p.ball_radius, g = p.gravity;
  const double vn = dot(k.v, n);
  if (vn <= 0.0 || z >= r) return std::nullopt;
  // The spin that rolls the ball along n is about a = z^ x n.
  const Vec3 axis{-n.y, n.x, 0.0};
  const double roll = dot(k.w, axis);
  // The edge is (r - z) below the centre and d ahead of it; the fall's speed is downward.
  const double d = std::sqrt(std::max(0.0, 2.0 * r * z - z * z));
  // Angular momentum about the edge, per unit mass, then as a rotation about it:
  // I_edge = 7/5 m r^2, so the centre's speed is u = L / (7/5 r).
  const double moment = (r - z) * vn - d * fall_speed + 0.4 * r * r * roll;
  const double u = moment / (1.4 * r);
  const double climb = u * u - g * z / 0.7;  // 7/10 u^2 against g z, per unit mass
  if (u <= 0.0 || climb <= 0.0) return std::nullopt;
  const double out = std::sqrt(climb);
  Kinematics after = k;
  after.v = k.v + n * (out - vn);
  after.w = k.w + axis * (out / r - roll);
  return after;
}

}  // namespace

PocketFall fallIntoPocket(const Kinematics& k, const Pocket& pocket, const Cushions& cushions,
                          const PhysicsParams& p) {
  PocketFall fall;
  const double r = p.ball_radius, g = p.gravity;
  // Once the centre is at the slate's level the edge is above its equator: no way back.
  const double deep = std::sqrt(2.0 * r / g);
  Kinematics at = k;
  double t = 0.0;
  for (int walls = 0; walls <= kMaxPocketWalls; ++walls) {
    const double horizon = deep - t;
    if (!(horizon > 0.0)) return fall;
    const auto edge = circleExit(at.p - pocket.drop_centre, at.v, pocket.drop_radius);
    const Path path{at.p, at.v, {}};
    const auto wall = cushionContact(path, r, cushions, std::min(horizon, edge.value_or(horizon)));
    if (edge && *edge < horizon && (!wall || *edge <= wall->s)) {
      const double te = t + *edge;
      const double z = 0.5 * g * te * te;
      Kinematics there = at;
      there.p = at.p + at.v * *edge;
      const Vec2 n = normalized(there.p - pocket.drop_centre);
      fall.drop = z;
      const auto out = climbOut(there, n, z, g * te, p);
      if (!out) return fall;
      fall.caught = false;
      fall.t_out = te;
      fall.out = *out;
      fall.out.p = pocket.drop_centre + n * (pocket.drop_radius + kOutside);
      return fall;
    }
    if (!wall || !(wall->s < horizon)) return fall;
    at.p = at.p + at.v * wall->s;
    t += wall->s;
    const double vn = dot(at.v, wall->normal);
    if (vn < 0.0) at.v = at.v - wall->normal * ((1.0 + p.pocket_restitution) * vn);
    fall.wall_contacts.push_back(at.v);
  }
  return fall;
}

}  // namespace nineball::physics
