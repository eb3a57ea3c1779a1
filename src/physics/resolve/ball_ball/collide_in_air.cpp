#include "physics/resolve/ball_ball/collide_in_air.hpp"

#include <cmath>

#include "physics/model/slate.hpp"

namespace nineball::physics {

void collideInAir(Kinematics& a, Kinematics& b, double mass_a, double mass_b,
                  const PhysicsParams& p) {
  const Vec2 d = b.p - a.p;
  const double dz = b.z - a.z;
  const double apart = std::sqrt(dot(d, d) + dz * dz);
  if (!(apart > 0.0)) return;
  const Vec2 n = d * (1.0 / apart);
  const double nz = dz / apart;
  const double closing = dot(a.v - b.v, n) + (a.vz - b.vz) * nz;
  if (closing > 0.0) {
    // The impulse per unit of closing speed: m_a m_b / (m_a + m_b), times (1 + e).
    const double impulse = (1.0 + p.ball_restitution) * closing / (1.0 / mass_a + 1.0 / mass_b);
    a.v = a.v - n * (impulse / mass_a);
    a.vz -= nz * impulse / mass_a;
    b.v = b.v + n * (impulse / mass_b);
    b.vz += nz * impulse / mass_b;
  }
  // A ball on the cloth pressed into the slate has it push back at once.
  if (a.z <= 0.0 && a.vz < 0.0) a = bounceOffSlate(a, p);
  if (b.z <= 0.0 && b.vz < 0.0) b = bounceOffSlate(b, p);
}

}  // namespace nineball::physics
