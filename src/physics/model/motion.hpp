#pragma once

#include <limits>

#include "nineball/params.hpp"
#include "nineball/vec2.hpp"
#include "nineball/vec3.hpp"

namespace nineball::physics {

/// What the cloth is doing to a ball: each phase has its own closed form.
enum class Phase {
  Sliding,   ///< the contact point slips: sliding friction against the slip (spin cloth)
  Rolling,   ///< rolling without slip (spin cloth), or the paper's and the damping cloth's motion
  Spinning,  ///< still on the cloth, turning about the vertical only
  Rest,
  /// In the air: a parabola under gravity alone, the spin carried (air drag neglected:
  /// docs/physics.md, "Balls in the air"); it ends as the ball meets the slate.
  Airborne,
};

const char* phaseName(Phase p);

/// A ball's position, velocity and angular velocity at one instant, and its height: z the height
/// of its centre above where it rests on the cloth (0 on the cloth), vz its vertical speed.
struct Kinematics {
  Vec2 p;
  Vec2 v;
  Vec3 w;
  double z = 0.0;
  double vz = 0.0;

  /// Off the cloth, or leaving it.
  bool flying() const { return z > 0.0 || vz > 0.0; }
};

constexpr double kNever = std::numeric_limits<double>::infinity();

/// One phase of a ball's motion from the instant t0 at which the last event changed it: the
/// closed form of the cloth model, valid for t0 <= t <= t0 + duration.
struct Arc {
  double t0 = 0.0;
  Kinematics start;
  Phase phase = Phase::Rest;
  Vec2 accel;                ///< m/s^2 while sliding or rolling (polynomial cloths)
  double duration = kNever;  ///< s until the phase ends by itself

  double end() const { return t0 + duration; }
  /// Sliding, rolling or in the air: the ball travels.
  bool translating() const {
    return phase == Phase::Sliding || phase == Phase::Rolling || phase == Phase::Airborne;
  }
};

/// The phase that starts at t0 from `k` under the cloth of `p`, with its closed form.
Arc beginArc(double t0, const Kinematics& k, const PhysicsParams& p);

/// The state on an arc at time t (clamped to the arc's end).
Kinematics stateAt(const Arc& arc, double t, const PhysicsParams& p);

/// The arc that follows `arc` once its phase ends by itself.
Arc nextArc(const Arc& arc, const PhysicsParams& p);

/// The common clock in which every ball's path is a polynomial: the time itself for the
/// polynomial cloths; for the damping cloth s = (1 - exp(-c tau)) / c, in which a damped
/// ball moves in a straight line at its present velocity.
struct Clock {
  double damping = 0.0;  ///< c, 1/s; 0 for the polynomial cloths

  static Clock of(const PhysicsParams& p);
  double fromTime(double tau) const;
  double toTime(double s) const;
};

/// A path over the clock s from a given instant: p + v s + a s^2 / 2.
struct Path {
  Vec2 p;
  Vec2 v;
  Vec2 a;

  Vec2 at(double s) const { return p + v * s + a * (0.5 * s * s); }
};

/// An axis-aligned box, for the cheap tests that come before any polynomial.
struct Box {
  double x0, x1, y0, y1;

  bool overlaps(const Box& o) const { return !(x0 > o.x1 || o.x0 > x1 || y0 > o.y1 || o.y0 > y1); }
  Box grown(double m) const { return {x0 - m, x1 + m, y0 - m, y1 + m}; }
};

/// The smallest box holding the path's point over s in [0, span] (everything when span is not
/// finite).
Box boxOf(const Path& path, double span);

/// The path of `arc` from time t on, in the clock's units, while the phase lasts.
Path pathFrom(const Arc& arc, double t, const PhysicsParams& p);

/// Velocity of the ball's contact point with the cloth: v + w x (0, 0, -R).
Vec2 slip(Vec2 v, Vec3 w, double radius);

/// Kinetic energy with rotation (I = 2/5 m R^2), J.
double kineticEnergy(const Kinematics& k, double mass, double radius);

}  // namespace nineball::physics
