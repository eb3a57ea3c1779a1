#include "physics/resolve/cushion/mathavan_speed/mathavan_speed.hpp"

#include <algorithm>

#include "physics/resolve/cushion/contact.hpp"
#include "physics/resolve/cushion/mathavan_2010/mathavan_2010.hpp"

namespace nineball::physics {

double speedRestitution(double speed, const PhysicsParams& p) {
  const double e = p.cushion_restitution_base + p.cushion_restitution_slope * speed +
                   p.cushion_restitution_quadratic * speed * speed;
  return std::clamp(e, std::min(p.cushion_restitution_min, 1.0), 1.0);
}

namespace {

// The normal rebound ratio of Mathavan's model with coefficient `e`, for a ball without spin
// straight in. The model is rigid and impulsive: the ratio is the same at every speed.
double straightInRatio(double e, double mass, const PhysicsParams& p) {
  PhysicsParams q = p;
  q.cushion_restitution = e;
  const Vec2 inward{0.0, 1.0};
  const Kinematics in{{0.0, 0.0}, {0.0, -1.0}, {0.0, 0.0, 0.0}};
  double impulse = 0.0;
  return dot(mathavanBounce(in, inward, mass, q, impulse).v, inward);
}

}  // namespace

double mathavanCoefficientFor(double target, double mass, const PhysicsParams& p) {
  if (target <= 0.0) return 0.0;
  // The ratio grows with the coefficient, in proportion while the slips keep their
  // directions through the restitution phase; three proportional corrections (a fixed number,
  // so that the answer is the same on every run) bring it within 1e-6 of the target.
  const double full = straightInRatio(1.0, mass, p);
  if (!(full > target)) return 1.0;
  double e = target / full;
  for (int n = 0; n < 3; ++n) {
    const double ratio = straightInRatio(e, mass, p);
    if (!(ratio > 0.0)) break;
    e = std::min(1.0, e * target / ratio);
  }
  return e;
}

Kinematics mathavanSpeedBounce(Kinematics k, Vec2 inward, double mass, const PhysicsParams& p,
                               double& impulse) {
  impulse = 0.0;
  const double speed = -dot(k.v, inward);
  if (!(speed > 0.0)) return k;
  PhysicsParams q = p;
  q.cushion_restitution = mathavanCoefficientFor(speedRestitution(speed, p), mass, p);
  return mathavanBounce(k, inward, mass, q, impulse);
}

namespace {

// As every cushion whose nose is the contact point (the curve's floor is checked where the
// parameters are read).
std::optional<std::string> check(const PhysicsParams& p) {
  return noseHeightFault(p, "the mathavan_speed cushion");
}

}  // namespace

CushionModelDef mathavanSpeedCushion() {
  CushionModelDef m;
  m.name = "mathavan_speed";
  m.bounce = mathavanSpeedBounce;
  m.reads = {"cushion_height", "cushion_restitution_base", "cushion_restitution_slope",
             "cushion_restitution_quadratic", "cushion_restitution_min"};
  m.ignores = {"cushion_restitution"};
  m.check = check;
  return m;
}

}  // namespace nineball::physics
