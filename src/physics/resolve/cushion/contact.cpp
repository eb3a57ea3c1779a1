#include "physics/resolve/cushion/contact.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "physics/resolve/ball_ball/collide.hpp"

namespace nineball::physics {

Kinematics stopAgainst(Kinematics k, const std::vector<Vec2>& normals, double mass,
                       double& impulse) {
  // The nearest velocity in the cone of allowed ones lies on one of its faces or at its apex.
  auto allowed = [&](Vec2 v) {
    for (Vec2 n : normals) {
      if (dot(v, n) < -1e-12) return false;
    }
    return true;
  };
  Vec2 best;
  if (allowed(k.v)) {
    best = k.v;
  } else {
    for (Vec2 n : normals) {
      const double vn = dot(k.v, n);
      const Vec2 v = k.v - n * vn;
      if (vn < 0.0 && allowed(v) && length(k.v - v) < length(k.v - best)) best = v;
    }
  }
  impulse = mass * length(k.v - best);
  k.v = best;
  return k;
}

Kinematics stopPressing(Kinematics k, Vec2 towards, const PhysicsParams& p) {
  if (!p.spin() || std::abs(dot(k.v, towards)) > kRestingSpeed) return k;
  const Vec2 u = slip(k.v, k.w, p.ball_radius);
  // Sliding friction acts against the slip: it presses when the slip points away.
  const double pressing = -dot(u, towards);
  if (pressing <= 0.0) return k;
  // The slip u = v + R (-w.y, w.x): cancel its component along `towards` through w alone. A
  // change q of that component changes the spin's energy by I/R^2 q (q/2 - pressing - v.t):
  // a ball already moving away (v.t < 0) could gain up to m (v.t)^2 / 5 from it, which at a
  // table's last millijoules is more than rounding. Only as much is cancelled as gives none.
  const double q = std::min(pressing, std::max(0.0, 2.0 * (pressing + dot(k.v, towards))));
  if (q <= 0.0) return k;
  const Vec2 du = towards * q;
  k.w.x += du.y / p.ball_radius;
  k.w.y -= du.x / p.ball_radius;
  return k;
}

bool touchesOnly(const Kinematics& k, Vec2 normal, const std::vector<Vec2>& faces, double r) {
  if (!(-dot(k.v, normal) > kMinClosingSpeed)) return true;
  // A ball on a rail within the tolerance meets the rail's end point at up to sqrt(2 tol / R)
  // from the rail's own normal, with the closing speed that angle gives its speed along the
  // rail: the rail ending under it, not a hit.
  for (Vec2 face : faces) {
    if (dot(face, normal) >= 1.0 - kTouchTolerance / r && !(-dot(k.v, face) > kMinClosingSpeed)) {
      return true;
    }
  }
  return false;
}

Kinematics restAgainstCushion(Kinematics k, Vec2 normal, const TableGeometry& table,
                              const PhysicsParams& p) {
  const double vn = dot(k.v, normal);
  if (vn < 0.0) k.v -= normal * vn;
  k = stopPressing(k, -normal, p);
  setOutOfCushion(k, normal, table, p.ball_radius);
  return k;
}

void setOutOfCushion(Kinematics& k, Vec2 normal, const TableGeometry& table, double r) {
  // Below half the tolerance a sink is the rounding of a contact met on time.
  const double sink = cushionSink(table, k.p, r);
  if (sink > 0.5 * kTouchTolerance) k.p += normal * sink;
}

std::optional<std::string> noseHeightFault(const PhysicsParams& p, const char* model) {
  const double r = p.ball_radius;
  if (p.cushion_height >= r && p.cushion_height < 2.0 * r) return std::nullopt;
  std::ostringstream why;
  why << "physics.cushion_height: " << model
      << "'s nose must stand no lower than the ball's centre and below its top: from " << r
      << " up to " << 2.0 * r << " m for ball_radius " << r;
  return why.str();
}

}  // namespace nineball::physics
