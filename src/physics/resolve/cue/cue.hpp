#pragma once

#include "nineball/params.hpp"
#include "nineball/shot.hpp"
#include "nineball/vec3.hpp"

namespace nineball::physics {

/// What a cue strike gives the cue ball.
struct Strike {
  Vec2 v;  ///< m/s, on the table
  Vec3 w;  ///< rad/s (zero for the cloths that carry no spin)
};

/// The cue delivers an impulse m * shot.speed along its axis, which is elevated by
/// shot.elevation_rad and meets the ball at the tip offset (side, height, as fractions of R,
/// seen along the cue). The slate takes the impulse's vertical part: the ball runs at
/// speed cos(elevation) (a jump is outside a 2-D game). Its spin is (r x J) / I with the full
/// 3-D contact point and impulse, so an elevated strike tilts the spin axis and the sliding
/// ball curves (swerve, masse). Side spin squirts the ball away from the side struck by
/// tan(a) = 5/2 b sqrt(1 - b^2) / (1 + m / m_e + 5/2 (1 - b^2)) (TP A.31), b the side offset
/// and m_e the cue's end mass (physics.cue_end_mass, 0 for none).
Strike cueStrike(const Shot& shot, double mass, const PhysicsParams& p);

/// The squirt angle (rad, positive to the left of the cue) for a side offset b (fraction of
/// R, positive to the right) of a ball of `mass` struck by a cue of end mass `end_mass`.
double squirtAngle(double b, double mass, double end_mass);

}  // namespace nineball::physics
