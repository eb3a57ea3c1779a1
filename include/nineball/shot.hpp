#pragma once

#include "nineball/vec2.hpp"

namespace nineball {

/// A cue strike on the cue ball.
struct Shot {
  double heading_rad = 0.0;    ///< direction of travel, anticlockwise from +x
  double speed = 0.0;          ///< m/s given to the cue ball
  Vec2 tip;                    ///< [side, height] as fractions of R (spin)
  double elevation_rad = 0.0;  ///< the cue's tilt above the table (0 to 89 degrees)

  /// A plain speed along a heading in degrees.
  static Shot withSpeed(double heading_deg, double speed);
  /// The paper's impulse (eq. 2.1-2.5): v = F dt / m.
  static Shot withImpulse(double heading_deg, double force, double contact_time, double mass);

  Vec2 velocity() const { return fromAngle(heading_rad) * speed; }
};

}  // namespace nineball
