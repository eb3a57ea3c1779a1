// Contacts never add energy, at any speed. One term did, at a table's last millijoules, where
// a gain of rounding size is more than the checked build's allowance (1e-6 of the table's
// energy): the spin change that stops a ball pressing on what it touches (after a ball-ball
// contact or a cushion bounce) gave up to m (v.t)^2 / 5 to a ball already moving away. Found
// by 150-200-ball runs without rolling resistance aborting the checked build after 140-260 s.
// Mathavan's cushion is held to the same property over slow and fast, spun and plain bounces.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "nineball/params.hpp"
#include "nineball/random.hpp"
#include "physics/model/motion.hpp"
#include "physics/resolve/cushion/contact.hpp"
#include "physics/resolve/cushion/mathavan_2010/mathavan_2010.hpp"

namespace nineball::physics {
namespace {

Vec3 randomSpin(std::uint64_t& rng, double scale) {
  return {uniform(rng, -scale, scale), uniform(rng, -scale, scale), uniform(rng, -scale, scale)};
}

TEST(ContactEnergy, StoppingThePressNeverAddsEnergy) {
  const PhysicsParams p = PhysicsParams::real();
  const double m = p.ball_mass, r = p.ball_radius;
  std::uint64_t rng = 11;
  for (int i = 0; i < 20000; ++i) {
    Kinematics k;
    // Slow along the obstacle's normal (stopPressing acts only there), any spin.
    const Vec2 towards = fromAngle(uniform(rng, -kPi, kPi));
    const double along = uniform(rng, -1.0, 1.0) * kRestingSpeed;
    k.v = towards * along + Vec2{-towards.y, towards.x} * uniform(rng, -0.01, 0.01);
    k.w = randomSpin(rng, uniform(rng, 0.0, 1.0) < 0.5 ? 0.01 / r : 1.0 / r);
    const double before = kineticEnergy(k, m, r);
    const Kinematics after = stopPressing(k, towards, p);
    EXPECT_LE(kineticEnergy(after, m, r), before * (1.0 + 1e-12)) << "case " << i;
  }
}

TEST(ContactEnergy, MathavansBounceNeverAddsEnergy) {
  std::uint64_t rng = 12;
  for (int i = 0; i < 4000; ++i) {
    PhysicsParams p = PhysicsParams::real();
    p.cushion_restitution = i % 3 == 0 ? 1.0 : uniform(rng, 0.0, 1.0);
    p.cushion_friction = uniform(rng, 0.0, 0.5);
    p.sliding_friction = uniform(rng, 0.0, 0.5);
    const double m = p.ball_mass, r = p.ball_radius;
    const Vec2 inward{0.0, -1.0};  // the top rail
    // From a tenth of a millimetre a second to a break's speed, spin up to the input's limit.
    const bool slow = i % 2 == 0;
    const double speed = std::pow(10.0, slow ? uniform(rng, -4.0, -2.0) : uniform(rng, -2.0, 1.0));
    Kinematics k;
    k.v = fromAngle(uniform(rng, 0.01, kPi - 0.01)) * speed;
    k.w = randomSpin(rng, slow ? uniform(rng, 0.0, 2.0) : uniform(rng, 0.0, 20.0 / r));
    const double before = kineticEnergy(k, m, r);
    double impulse = 0.0;
    const Kinematics after = mathavanBounce(k, inward, m, p, impulse);
    EXPECT_LE(kineticEnergy(after, m, r), before * (1.0 + 1e-12))
        << "case " << i << ": " << speed << " m/s, e " << p.cushion_restitution;
  }
}

}  // namespace
}  // namespace nineball::physics
