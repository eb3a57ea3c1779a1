#include "physics/model/slate.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::physics {

bool airborneAllowed(const PhysicsParams& p) {
  return p.cloth == ClothModel::Spin;
}

double landingTime(double z, double vz, double g) {
  const double root = std::sqrt(vz * vz + 2.0 * g * std::max(z, 0.0));
  if (vz >= 0.0) return (vz + root) / g;
  return 2.0 * std::max(z, 0.0) / (root - vz);
}

double bounceHeight(double vz, double g) {
  return 0.5 * vz * vz / g;
}

Kinematics bounceOffSlate(Kinematics k, const PhysicsParams& p) {
  if (!(k.vz < 0.0)) return k;
  const double e = p.table_restitution;
  // The normal impulse per unit mass, and the friction it can bring to bear on the slip.
  const double normal = (1.0 + e) * -k.vz;
  const Vec2 u = slip(k.v, k.w, p.ball_radius);
  const double us = length(u);
  if (us > 0.0) {
    // The slip of a sphere changes by 7/2 of the friction's change of velocity: 2/7 ends it.
    const double change = std::min(p.sliding_friction * normal, us / 3.5);
    const Vec2 along = u * (1.0 / us);
    k.v = k.v - along * change;
    const double turn = 2.5 * change / p.ball_radius;
    k.w = {k.w.x - turn * along.y, k.w.y + turn * along.x, k.w.z};
  }
  k.z = 0.0;
  k.vz = e * -k.vz;
  if (bounceHeight(k.vz, p.gravity) < p.min_bounce_height) k.vz = 0.0;
  return k;
}

double strikeRebound(double vz, const PhysicsParams& p) {
  if (!(vz < 0.0) || !airborneAllowed(p)) return 0.0;
  const double up = p.table_restitution * -vz;
  return bounceHeight(up, p.gravity) < p.min_bounce_height ? 0.0 : up;
}

double mechanicalEnergy(const Kinematics& k, double mass, double radius, double g) {
  return kineticEnergy(k, mass, radius) + mass * g * k.z;
}

}  // namespace nineball::physics
