#include "physics/resolve/cushion/simple/simple.hpp"

#include <algorithm>

#include "physics/resolve/cushion/contact.hpp"

namespace nineball::physics {

Kinematics bounceOffCushion(Kinematics k, Vec2 normal, double mass, const PhysicsParams& p,
                            double& impulse) {
  const double vn = dot(k.v, normal);
  impulse = 0.0;
  if (vn >= 0.0) return k;
  const double e = -vn > kRestingSpeed ? p.cushion_restitution : 0.0;
  impulse = -(1.0 + e) * vn * mass;
  k.v -= normal * ((1.0 + e) * vn);
  return k;
}

Kinematics cushionFriction(Kinematics k, Vec2 normal, double normal_impulse, double mass,
                           const PhysicsParams& p) {
  if (!p.spin() || p.cushion_friction <= 0.0 || normal_impulse <= 0.0) return k;
  const double r = p.ball_radius;
  const Vec3 arm = lift(normal * -r);  // from the centre to the nose
  const Vec2 at_contact = flat(lift(k.v) + cross(k.w, arm));
  const Vec2 sliding = at_contact - normal * dot(at_contact, normal);
  const double speed = length(sliding);
  if (speed < 1e-12) return k;
  const double grip = 2.0 / 7.0 * mass * speed;
  const Vec2 impulse = sliding * (-std::min(p.cushion_friction * normal_impulse, grip) / speed);
  const double inertia = 0.4 * mass * r * r;
  k.v += impulse / mass;
  k.w = k.w + cross(arm, lift(impulse)) * (1.0 / inertia);
  return k;
}

CushionModelDef simpleCushion() {
  CushionModelDef m;
  m.name = "simple";
  return m;
}

}  // namespace nineball::physics
