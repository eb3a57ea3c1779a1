#include "physics/cloth.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::physics {
namespace {

// Slip below this (m/s) is rolling: the exact transition lands on it within rounding.
constexpr double kRollingSlip = 1e-9;

// Rolling: w follows v about the horizontal axes.
Vec3 rollingSpin(Vec2 v, double wz, double radius) {
  return {-v.y / radius, v.x / radius, wz};
}

double decaySpin(double wz, double rate, double h) {
  const double dw = rate * h;
  if (std::abs(wz) <= dw) return 0.0;
  return wz > 0.0 ? wz - dw : wz + dw;
}

}  // namespace

Vec2 slip(const Motion& m, double radius) {
  return {m.v.x - radius * m.w.y, m.v.y + radius * m.w.x};
}

ClothStep slideAndRoll(Motion m, double h, const PhysicsParams& p) {
  const double r = p.ball_radius;
  const double g = p.gravity;
  ClothStep out;
  const double wz = decaySpin(m.w.z, p.spin_decay, h);
  double left = h;
  const Vec2 u = slip(m, r);
  const double us = length(u);
  if (us > kRollingSlip && p.sliding_friction > 0.0) {
    const Vec2 dir = u / us;
    const double t_roll = 2.0 * us / (7.0 * p.sliding_friction * g);
    const double t = std::min(left, t_roll);
    const double a = p.sliding_friction * g;
    const double alpha = 5.0 * a / (2.0 * r);
    m.v -= dir * (a * t);
    m.w.x -= alpha * dir.y * t;
    m.w.y += alpha * dir.x * t;
    left -= t;
    if (left <= 0.0) {
      m.w.z = wz;
      out.end = m;
      return out;
    }
  } else if (us > kRollingSlip) {
    m.w.z = wz;
    out.end = m;  // no sliding friction: the slip never ends
    return out;
  }
  // Rolling for what is left of the interval.
  const double speed = length(m.v);
  const double decel = p.rolling_friction * g;
  if (speed <= decel * left) {
    if (speed > 0.0 || m.w.x != 0.0 || m.w.y != 0.0) {
      out.stopped_after = (h - left) + (decel > 0.0 ? speed / decel : 0.0);
    }
    out.end = {{}, {}};
    return out;
  }
  const Vec2 v = speed > 0.0 ? m.v * ((speed - decel * left) / speed) : m.v;
  out.end = {v, rollingSpin(v, wz, r)};
  return out;
}

ClothStep decelerate(Motion m, double h, const PhysicsParams& p) {
  ClothStep out;
  const double decel = p.rolling_friction * p.gravity;
  const double speed = length(m.v);
  if (decel <= 0.0 || speed == 0.0) {
    out.end = m;
    return out;
  }
  if (speed <= decel * h) {
    out.stopped_after = speed / decel;
    out.end = {{}, m.w};
    return out;
  }
  out.end = {m.v * ((speed - decel * h) / speed), m.w};
  return out;
}

Vec3 strikeSpin(Vec2 dir, double speed, Vec2 tip, double radius) {
  // r x (J d) = J R (side z + height (-dy, dx, 0)), I = 2/5 m R^2, J = m v.
  const double k = 5.0 * speed / (2.0 * radius);
  return {-dir.y * tip.y * k, dir.x * tip.y * k, tip.x * k};
}

}  // namespace nineball::physics
