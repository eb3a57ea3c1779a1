#pragma once

#include <optional>

#include "nineball/params.hpp"
#include "nineball/vec2.hpp"
#include "nineball/vec3.hpp"

namespace nineball::physics {

/// A ball's motion: linear velocity on the table and angular velocity (z up).
struct Motion {
  Vec2 v;
  Vec3 w;
};

/// The motion after some time on the cloth, and when within it the ball came to rest.
struct ClothStep {
  Motion end;
  std::optional<double> stopped_after;  ///< s from the start of the interval
};

/// Velocity of the ball's contact point with the cloth: v + w x (0, 0, -R).
Vec2 slip(const Motion& m, double radius);

/// The spin model over h seconds, solved exactly: while the contact point slips, sliding
/// friction mu_s m g acts against the slip (whose direction stays fixed; it shrinks at 7/2
/// mu_s g) on both v and w (I = 2/5 m R^2); once it rolls (v = R w), rolling resistance
/// mu_r g slows it with w following; spin about the vertical decays at spin_decay.
ClothStep slideAndRoll(Motion m, double h, const PhysicsParams& p);

/// The paper's cloth over h seconds: constant deceleration mu g against v (eq. 4.5-4.8).
ClothStep decelerate(Motion m, double h, const PhysicsParams& p);

/// Angular velocity a level cue gives a ball at speed `speed` along unit `dir`, struck at
/// `tip` = [side, height] fractions of R (paper eq. 3.16-3.21: w = r x F dt / I).
Vec3 strikeSpin(Vec2 dir, double speed, Vec2 tip, double radius);

}  // namespace nineball::physics
