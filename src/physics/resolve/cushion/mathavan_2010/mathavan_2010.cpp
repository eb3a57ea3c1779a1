#include "physics/resolve/cushion/mathavan_2010/mathavan_2010.hpp"

#include <algorithm>
#include <cmath>

#include "physics/resolve/cushion/contact.hpp"

namespace nineball::physics {
namespace {

// The ball in the cushion's frame: x along the cushion, y into it, z up.
struct State {
  double vx, vy, wx, wy, wz;
};

struct Contact {
  double mass, radius, sin_t, cos_t, mu_w, mu_s;
  // Slips slower than this (m/s) are regularised: friction in proportion to the slip. A slip
  // that stops and would reverse is then held near zero (sticking) smoothly, instead of
  // flipping direction from step to step, which made the rebound jump with the last digit
  // of the input.
  double stick;

  // d(state)/dP: the paper's equations of motion (its eq. 17), the slip directions taken
  // from the state itself.
  State rate(const State& s) const {
    const double r = radius;
    const double xi = s.vx + s.wy * r * sin_t - s.wz * r * cos_t;  // slip at I, along x
    const double yi = -s.vy * sin_t + s.wx * r;                    // slip at I, across
    const double xc = s.vx - s.wy * r;                             // slip at C
    const double yc = s.vy + s.wx * r;
    // Slips are speeds of a few m/s: their squares can neither overflow nor underflow below
    // the regularisation, so sqrt serves where hypot's care costs four times as much.
    const double si = std::max(std::sqrt(xi * xi + yi * yi), stick);
    const double sc = std::max(std::sqrt(xc * xc + yc * yc), stick);
    const double cos_i = xi / si, sin_i = yi / si, cos_c = xc / sc, sin_c = yc / sc;
    // The slate's normal force per unit P: the nose presses down by sin(theta), and the
    // nose's friction adds its vertical share. The slate can only push: when the nose's
    // friction would lift the ball (a low nose, a rough cushion) it carries no load, and
    // its friction none either (else that friction would drive the ball and add energy).
    const double slate = std::max(0.0, sin_t + mu_w * sin_i * cos_t);
    const double spin = 5.0 / (2.0 * mass * r);
    return {-(mu_w * cos_i + mu_s * cos_c * slate) / mass,
            -(cos_t - mu_w * sin_t * sin_i + mu_s * sin_c * slate) / mass,
            -spin * (mu_w * sin_i + mu_s * sin_c * slate),
            -spin * (mu_w * cos_i * sin_t - mu_s * cos_c * slate), spin * mu_w * cos_i * cos_t};
  }

  // One midpoint step of size dp.
  State step(const State& s, double dp) const {
    const State a = rate(s);
    const double h = 0.5 * dp;
    const State mid{s.vx + a.vx * h, s.vy + a.vy * h, s.wx + a.wx * h, s.wy + a.wy * h,
                    s.wz + a.wz * h};
    const State b = rate(mid);
    return {s.vx + b.vx * dp, s.vy + b.vy * dp, s.wx + b.wx * dp, s.wy + b.wy * dp,
            s.wz + b.wz * dp};
  }
};

// Steps per phase: the midpoint rule's error falls as 1/N^2. The regularisation is sized for
// them: one step's friction (about 7/2 (mu_w + mu_s) vy / (N cos theta) of slip) is no more
// than it, so the integration stays stable for every allowed friction. The stiff stretch where
// a slip stops sets the step: an adaptive Runge-Kutta 3(2) pair, tried, took four times the
// work to stay stable there. Mathavan.HundredStepsAgainstTwentyThousand states the accuracy.
constexpr int kSteps = 100;

// The rebound with `steps` fixed midpoint steps a phase.
State fixedStepBounce(State s, const Contact& c, const PhysicsParams& p, int steps,
                      double& impulse) {
  // Compression: until the ball stops moving into the cushion. Its normal speed at I is
  // vy cos(theta); the work the normal force takes is the integral of that over P.
  const double dp = c.mass * s.vy / (c.cos_t * steps);
  double work = 0.0;
  for (int n = 0; n < 100 * steps && s.vy > 0.0; ++n) {
    State next = c.step(s, dp);
    double used = dp;
    if (next.vy < 0.0) {  // the last step, cut where vy reaches 0
      used = dp * s.vy / (s.vy - next.vy);
      next = c.step(s, used);
      next.vy = 0.0;
    }
    work += used * c.cos_t * 0.5 * (s.vy + std::max(next.vy, 0.0));
    impulse += used;
    s = next;
  }
  const double target = p.cushion_restitution * p.cushion_restitution * work;
  double given = 0.0;
  for (int n = 0; n < 100 * steps && given < target; ++n) {
    const double speed = -s.vy * c.cos_t;
    // Size the step from what is left; at the start (vy = 0) one of compression's size.
    double step = dp;
    if (speed > 0.0) step = std::min(dp, (target - given) / speed);
    const State next = c.step(s, step);
    given += step * c.cos_t * 0.5 * (-s.vy - next.vy);
    impulse += step;
    s = next;
    if (step < dp) break;  // that step reached the target
  }
  return s;
}

Kinematics bounce(Kinematics k, Vec2 inward, double mass, const PhysicsParams& p, int steps,
                  double& impulse) {
  impulse = 0.0;
  const Vec2 y = inward * -1.0;  // into the cushion
  const Vec2 x{y.y, -y.x};       // x cross y = z
  State s{dot(k.v, x), dot(k.v, y), k.w.x * x.x + k.w.y * x.y, k.w.x * y.x + k.w.y * y.y, k.w.z};
  if (s.vy <= 0.0) return k;
  const double r = p.ball_radius;
  const double sin_t = (p.cushion_height - r) / r;
  // Regularised below a slip of a few per cent of the approach speed (see kSteps).
  const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
  const double stick =
      s.vy * std::max(0.01, 3.5 * (p.cushion_friction + p.sliding_friction) / (cos_t * kSteps));
  const Contact c{mass, r, sin_t, cos_t, p.cushion_friction, p.sliding_friction, stick};
  s = fixedStepBounce(s, c, p, steps, impulse);
  k.v = x * s.vx + y * s.vy;
  k.w = {x.x * s.wx + y.x * s.wy, x.y * s.wx + y.y * s.wy, s.wz};
  return k;
}

}  // namespace

Kinematics mathavanBounce(Kinematics k, Vec2 inward, double mass, const PhysicsParams& p,
                          double& impulse) {
  return bounce(k, inward, mass, p, kSteps, impulse);
}

Kinematics mathavanBounceInSteps(Kinematics k, Vec2 inward, double mass, const PhysicsParams& p,
                                 int steps, double& impulse) {
  return bounce(k, inward, mass, p, steps, impulse);
}

namespace {

std::optional<std::string> mathavanHeightFault(const PhysicsParams& p) {
  return noseHeightFault(p, "the Mathavan cushion");
}

}  // namespace

CushionModelDef mathavan2010Cushion() {
  CushionModelDef m;
  m.name = "mathavan";
  m.bounce = mathavanBounce;
  m.reads = {"cushion_height"};
  m.check = mathavanHeightFault;
  return m;
}

}  // namespace nineball::physics
