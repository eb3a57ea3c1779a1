// Ball-ball friction against Alciatore's closed form (TP A.14), with the reference values of
// ../shared/physics-models.md: the form with the normal speed (1+e)/2 v cos phi at e = 0.95 (the
// figures TP A.14 publishes, 4.72 and 2.19 deg at 30 and 15 deg, are elastic). Tolerance 0.2 deg
// (the issue's): the reference values are printed to 0.01 deg, and the closed form and the 3-D
// impulse differ only by rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "nineball/params.hpp"
#include "nineball/vec2.hpp"
#include "physics/model/motion.hpp"
#include "physics/resolve/ball_ball/ball_contact.hpp"

namespace nineball::physics {
namespace {

constexpr double kToleranceDeg = 0.2;

double deg(double rad) {
  return rad * 180.0 / kPi;
}

struct Hit {
  double throw_deg;     // the object ball's direction off the line of centres
  double energy_ratio;  // kinetic energy, rotation included, after / before
  Vec3 object_spin;
};

// A cue ball at `speed` along +x with spin `w` meets a resting object ball at cut angle phi.
Hit hit(double phi_deg, double speed, Vec3 w, const PhysicsParams& p) {
  const double r = p.ball_radius, m = p.ball_mass, phi = phi_deg * kPi / 180.0;
  Kinematics cue{{0.0, 0.0}, {speed, 0.0}, w};
  Kinematics object{{2.0 * r * std::cos(phi), -2.0 * r * std::sin(phi)}, {}, {}};
  const double before = kineticEnergy(cue, m, r);
  collideBalls(cue, object, m, m, p);
  const Vec2 n = normalized(object.p - cue.p);
  const double along = dot(object.v, n), across = cross(n, object.v);
  return {deg(std::atan2(std::abs(across), along)),
          (kineticEnergy(cue, m, r) + kineticEnergy(object, m, r)) / before, object.w};
}

// TP A.14's closed form, with the cap where the contact points stop sliding.
double closedFormDeg(double phi_deg, double speed, double side, double top,
                     const PhysicsParams& p) {
  const double phi = phi_deg * kPi / 180.0, e = p.ball_restitution;
  const double slip_side = speed * std::sin(phi) - side, slip_up = top * std::cos(phi);
  const double v_rel = std::hypot(slip_side, slip_up);
  if (v_rel == 0.0) return 0.0;
  const double mu = p.ball_friction.at(v_rel);
  const double normal = (1.0 + e) / 2.0 * speed * std::cos(phi);
  const double tangential = std::min(mu * normal, v_rel / 7.0) * std::abs(slip_side) / v_rel;
  return deg(std::atan2(tangential, normal));
}

TEST(Throw, CutInducedStunMatchesTheMeasuredCurve) {
  const PhysicsParams p = PhysicsParams::real();
  struct Case {
    double phi, speed, reference;
  };
  const Case references[] = {{15, 0.5, 2.25}, {15, 1.0, 2.25}, {15, 2.0, 2.25},
                             {30, 0.5, 4.84}, {30, 1.0, 4.15}, {30, 2.0, 2.65},
                             {45, 0.5, 4.77}, {45, 1.0, 3.43}, {45, 2.0, 1.90}};
  for (const Case& c : references) {
    const Hit h = hit(c.phi, c.speed, {}, p);
    std::printf("[ measured ] throw, stun, cut %.0f deg at %.1f m/s: %.2f deg (reference %.2f)\n",
                c.phi, c.speed, h.throw_deg, c.reference);
    EXPECT_NEAR(h.throw_deg, c.reference, kToleranceDeg) << c.phi << " deg at " << c.speed;
    EXPECT_LE(h.energy_ratio, 1.0 + 1e-12);
  }
}

TEST(Throw, EveryCutAndSpeedFollowsTheClosedFormStunAndRolling) {
  const PhysicsParams p = PhysicsParams::real();
  const double r = p.ball_radius;
  for (double speed : {0.5, 1.0, 2.0}) {
    for (int phi = 0; phi <= 60; phi += 5) {
      const Hit stun = hit(phi, speed, {}, p);
      EXPECT_NEAR(stun.throw_deg, closedFormDeg(phi, speed, 0.0, 0.0, p), kToleranceDeg);
      // Rolling along +x: w_y = v / R.
      const Hit rolling = hit(phi, speed, {0.0, speed / r, 0.0}, p);
      EXPECT_NEAR(rolling.throw_deg, closedFormDeg(phi, speed, 0.0, speed, p), kToleranceDeg);
      if (phi > 0) {
        EXPECT_LT(rolling.throw_deg, stun.throw_deg + 1e-12) << phi << " " << speed;
      }
      EXPECT_LE(stun.energy_ratio, 1.0 + 1e-12);
      EXPECT_LE(rolling.energy_ratio, 1.0 + 1e-12);
    }
  }
}

TEST(Throw, SpinInducedStraightInMatchesTheMeasuredCurve) {
  // Straight in with running side spin R wz = v: the object ball leaves off the line.
  const PhysicsParams p = PhysicsParams::real();
  const double r = p.ball_radius;
  const double published[][2] = {{0.5, 4.15}, {1.0, 2.65}, {2.0, 1.27}};
  for (const auto& [speed, expected] : published) {
    const Hit h = hit(0.0, speed, {0.0, 0.0, speed / r}, p);
    std::printf(
        "[ measured ] throw, straight in, R wz = v at %.1f m/s: %.2f deg (reference %.2f)\n", speed,
        h.throw_deg, expected);
    EXPECT_NEAR(h.throw_deg, expected, kToleranceDeg);
    EXPECT_LE(h.energy_ratio, 1.0 + 1e-12);
  }
}

TEST(Throw, FrictionPassesSpinToTheObjectBall) {
  // A cut stun shot drags the object ball's near side along: it leaves with side spin of the
  // opposite sense to the cue ball's throw direction (gear effect), and the paper's
  // frictionless model passes none.
  PhysicsParams p = PhysicsParams::real();
  const Hit h = hit(30.0, 1.0, {}, p);
  EXPECT_GT(std::abs(h.object_spin.z), 1.0);
  p.ball_ball = BallBallModel::named("frictionless");
  const Hit none = hit(30.0, 1.0, {}, p);
  EXPECT_NEAR(none.throw_deg, 0.0, 1e-9);
  EXPECT_EQ(none.object_spin.z, 0.0);
}

}  // namespace
}  // namespace nineball::physics
