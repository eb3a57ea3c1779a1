#include "physics/resolve/ball_ball/frictional/frictional.hpp"

#include <algorithm>

namespace nineball::physics {
namespace {

// Ball-ball friction (Alciatore, TP A.14): a tangential impulse against the sliding of the
// contact points, mu(sliding speed) times the normal impulse, capped where they stop sliding.
// The sliding includes the vertical part topspin and draw give it, so a rolling ball throws
// less. Each ball's contact point answers a surface impulse J by J/m + J R^2/I = 7/2 J/m, so
// sliding stops at |u| / (7/2 (1/m_a + 1/m_b)): 1/7 of m|u| for equal balls. The vertical part
// of the impulse goes into the slate (a hop from it is not modelled); its spin stays.
void grip(Kinematics& a, Kinematics& b, double mass_a, double mass_b, Vec2 n, double normal_impulse,
          const PhysicsParams& p) {
  const double r = p.ball_radius;
  const Vec3 n3 = lift(n), arm_a = n3 * r, arm_b = n3 * -r;
  Vec3 u = (lift(a.v) + cross(a.w, arm_a)) - (lift(b.v) + cross(b.w, arm_b));
  u = u - n3 * dot(u, n3);
  const double sliding = length(u);
  if (sliding < 1e-12 || normal_impulse <= 0.0) return;
  const double stop = sliding / (3.5 * (1.0 / mass_a + 1.0 / mass_b));
  const double size = std::min(p.ball_friction.at(sliding) * normal_impulse, stop);
  const Vec3 on_a = u * (-size / sliding);
  a.v += flat(on_a) / mass_a;
  b.v -= flat(on_a) / mass_b;
  if (!p.spin()) return;  // the other cloths carry no spin
  a.w = a.w + cross(arm_a, on_a) * (1.0 / (0.4 * mass_a * r * r));
  b.w = b.w + cross(arm_b, on_a * -1.0) * (1.0 / (0.4 * mass_b * r * r));
}

}  // namespace

BallBallModelDef frictionalBallBall() {
  BallBallModelDef m;
  m.name = "frictional";
  m.grip = grip;
  m.reads = {"ball_friction"};
  return m;
}

}  // namespace nineball::physics
