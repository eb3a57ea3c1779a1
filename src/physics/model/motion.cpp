#include "physics/model/motion.hpp"

#include <algorithm>
#include <cmath>

#include "physics/model/slate.hpp"

namespace nineball::physics {
namespace {

// Slip below this (m/s) is rolling: the exact transition lands on it within rounding.
constexpr double kRollingSlip = 1e-9;

Vec3 rollingSpin(Vec2 v, double wz, double radius) {
  return {-v.y / radius, v.x / radius, wz};
}

// Spin about the vertical falls linearly to zero and stays there.
double decaySpin(double wz, double rate, double tau) {
  const double dw = rate * tau;
  if (std::abs(wz) <= dw) return 0.0;
  return wz > 0.0 ? wz - dw : wz + dw;
}

double timeToStop(double speed, double decel) {
  return decel > 0.0 ? speed / decel : kNever;
}

Arc restOrSpin(Arc arc, const PhysicsParams& p) {
  arc.start.v = {};
  arc.start.w = {0.0, 0.0, p.spin() ? arc.start.w.z : 0.0};
  arc.accel = {};
  if (arc.start.w.z != 0.0) {
    arc.phase = Phase::Spinning;
    arc.duration = timeToStop(std::abs(arc.start.w.z), p.spin_decay);
  } else {
    arc.phase = Phase::Rest;
    arc.duration = kNever;
  }
  return arc;
}

}  // namespace

const char* phaseName(Phase p) {
  switch (p) {
    case Phase::Sliding:
      return "sliding";
    case Phase::Rolling:
      return "rolling";
    case Phase::Spinning:
      return "spinning";
    case Phase::Rest:
      return "rest";
    case Phase::Airborne:
      return "airborne";
  }
  return "?";
}

Vec2 slip(Vec2 v, Vec3 w, double radius) {
  return {v.x - radius * w.y, v.y + radius * w.x};
}

Arc beginArc(double t0, const Kinematics& k, const PhysicsParams& p) {
  Arc arc;
  arc.t0 = t0;
  arc.start = k;
  if (k.flying() && airborneAllowed(p)) {
    arc.phase = Phase::Airborne;
    arc.duration = landingTime(k.z, k.vz, p.gravity);
    return arc;
  }
  arc.start.z = 0.0;
  arc.start.vz = 0.0;
  const double speed = length(k.v);
  switch (p.cloth) {
    case ClothModel::Spin: {
      const Vec2 u = slip(k.v, k.w, p.ball_radius);
      const double us = length(u);
      if (us > kRollingSlip) {
        arc.phase = Phase::Sliding;
        const double mu_g = p.sliding_friction * p.gravity;
        arc.accel = u * (-mu_g / us);
        arc.duration = timeToStop(2.0 * us, 7.0 * mu_g);
        return arc;
      }
      if (speed == 0.0) return restOrSpin(arc, p);
      arc.phase = Phase::Rolling;
      arc.start.w = rollingSpin(k.v, k.w.z, p.ball_radius);
      const double decel = p.rolling_friction * p.gravity;
      arc.accel = k.v * (-decel / speed);
      arc.duration = timeToStop(speed, decel);
      return arc;
    }
    case ClothModel::Friction: {
      arc.start.w = {};
      if (speed == 0.0) return restOrSpin(arc, p);
      arc.phase = Phase::Rolling;
      const double decel = p.rolling_friction * p.gravity;
      arc.accel = k.v * (-decel / speed);
      arc.duration = timeToStop(speed, decel);
      return arc;
    }
    case ClothModel::Damping: {
      arc.start.w = {};
      if (speed == 0.0 || speed <= p.rest_speed) return restOrSpin(arc, p);
      arc.phase = Phase::Rolling;
      // v(t) = v0 exp(-c t) reaches rest_speed after ln(v0 / rest_speed) / c.
      const double c = p.linear_damping;
      arc.duration = c > 0.0 && p.rest_speed > 0.0 ? std::log(speed / p.rest_speed) / c : kNever;
      return arc;
    }
  }
  return arc;
}

Kinematics stateAt(const Arc& arc, double t, const PhysicsParams& p) {
  const double tau = std::clamp(t - arc.t0, 0.0, arc.duration);
  const Kinematics& k = arc.start;
  Kinematics out = k;
  switch (arc.phase) {
    case Phase::Rest:
      return out;
    case Phase::Spinning:
      out.w.z = decaySpin(k.w.z, p.spin_decay, tau);
      return out;
    case Phase::Airborne:
      out.p = k.p + k.v * tau;
      out.z = k.z + k.vz * tau - 0.5 * p.gravity * tau * tau;
      out.vz = k.vz - p.gravity * tau;
      return out;
    case Phase::Sliding:
    case Phase::Rolling:
      break;
  }
  if (p.cloth == ClothModel::Damping) {
    const Clock clock = Clock::of(p);
    out.p = k.p + k.v * clock.fromTime(tau);
    out.v = k.v * std::exp(-clock.damping * tau);
    return out;
  }
  out.p = k.p + k.v * tau + arc.accel * (0.5 * tau * tau);
  out.v = k.v + arc.accel * tau;
  if (!p.spin()) return out;
  const double wz = decaySpin(k.w.z, p.spin_decay, tau);
  if (arc.phase == Phase::Rolling) {
    out.w = rollingSpin(out.v, wz, p.ball_radius);
  } else {
    // Sliding friction F = m a at the contact point (0, 0, -R): I dw = (-R z) x F dt.
    const double f = 2.5 / p.ball_radius;
    out.w = {k.w.x + f * arc.accel.y * tau, k.w.y - f * arc.accel.x * tau, wz};
  }
  return out;
}

Arc nextArc(const Arc& arc, const PhysicsParams& p) {
  Kinematics k = stateAt(arc, arc.end(), p);
  switch (arc.phase) {
    case Phase::Airborne: {
      // The ball meets the slate: it lands exactly on it, at the speed of the closed form.
      k.z = 0.0;
      k.vz = -std::sqrt(arc.start.vz * arc.start.vz + 2.0 * p.gravity * arc.start.z);
      return beginArc(arc.end(), bounceOffSlate(k, p), p);
    }
    case Phase::Sliding: {
      // The slip has just vanished: the ball rolls from here.
      Arc next = beginArc(arc.end(), k, p);
      if (next.phase == Phase::Sliding) {
        k.w = rollingSpin(k.v, k.w.z, p.ball_radius);
        next = beginArc(arc.end(), k, p);
      }
      return next;
    }
    case Phase::Rolling:
    case Phase::Spinning:
    case Phase::Rest: {
      Arc still;
      still.t0 = arc.end();
      still.start = k;
      if (arc.phase == Phase::Spinning) still.start.w.z = 0.0;
      return restOrSpin(still, p);
    }
  }
  return arc;
}

Clock Clock::of(const PhysicsParams& p) {
  return {p.cloth == ClothModel::Damping ? p.linear_damping : 0.0};
}

double Clock::fromTime(double tau) const {
  if (damping == 0.0) return tau;
  return -std::expm1(-damping * tau) / damping;
}

double Clock::toTime(double s) const {
  if (damping == 0.0) return s;
  const double x = damping * s;
  return x >= 1.0 ? kNever : -std::log1p(-x) / damping;
}

namespace {

// The extent of p + v s + a s^2 / 2 over s in [0, span], on one axis.
void extent(double p, double v, double a, double span, double& lo, double& hi) {
  const double end = p + v * span + 0.5 * a * span * span;
  lo = std::min(p, end);
  hi = std::max(p, end);
  if (a != 0.0) {
    const double s = -v / a;
    if (s > 0.0 && s < span) {
      const double turn = p + v * s + 0.5 * a * s * s;
      lo = std::min(lo, turn);
      hi = std::max(hi, turn);
    }
  }
}

}  // namespace

Box boxOf(const Path& path, double span) {
  if (!std::isfinite(span)) return {-kNever, kNever, -kNever, kNever};
  Box b{};
  extent(path.p.x, path.v.x, path.a.x, span, b.x0, b.x1);
  extent(path.p.y, path.v.y, path.a.y, span, b.y0, b.y1);
  return b;
}

Path pathFrom(const Arc& arc, double t, const PhysicsParams& p) {
  const Kinematics k = stateAt(arc, t, p);
  if (!arc.translating()) return {k.p, {}, {}};
  return {k.p, k.v, p.cloth == ClothModel::Damping ? Vec2{} : arc.accel};
}

double kineticEnergy(const Kinematics& k, double mass, double radius) {
  const double inertia = 0.4 * mass * radius * radius;
  return 0.5 * mass * (dot(k.v, k.v) + k.vz * k.vz) +
         0.5 * inertia * (k.w.x * k.w.x + k.w.y * k.w.y + k.w.z * k.w.z);
}

}  // namespace nineball::physics
