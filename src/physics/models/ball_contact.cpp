#include "physics/models/ball_contact.hpp"

#include "physics/ball_collision.hpp"
#include "physics/models/cushion.hpp"

namespace nineball::physics {

void collideBalls(Kinematics& a, Kinematics& b, double mass_a, double mass_b,
                  const PhysicsParams& p) {
  const Vec2 n = normalized(b.p - a.p);
  const auto out = collide(a.v, b.v, mass_a, mass_b, p.ball_restitution, n);
  a.v = out.v1;
  b.v = out.v2;
  if (dot(b.v - a.v, n) < kRestingSpeed) {
    a = stopPressing(a, n, p);
    b = stopPressing(b, -n, p);
  }
}

}  // namespace nineball::physics
