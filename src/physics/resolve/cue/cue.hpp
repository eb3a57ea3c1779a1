#pragma once

#include <optional>
#include <vector>

#include "nineball/event.hpp"
#include "nineball/params.hpp"
#include "nineball/shot.hpp"
#include "nineball/vec3.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

/// What a cue strike gives the cue ball.
struct Strike {
  Vec2 v;         ///< m/s, on the table
  Vec3 w;         ///< rad/s (zero for the cloths that carry no spin)
  double vz = 0;  ///< m/s upward, the slate's rebound (0: the ball stays on the cloth)
  /// The tip met the ball below its equator while the stroke lifts it off the cloth: the tip
  /// gets under the ball (a scoop), a miscue.
  bool scoop = false;
};

/// The cue delivers an impulse m * shot.speed along its axis, which is elevated by
/// shot.elevation_rad and meets the ball at the tip offset (side, height, as fractions of R,
/// seen along the cue). The ball runs at speed cos(elevation) on the table; the impulse's
/// vertical part drives it into the slate, which returns it times table_restitution
/// (strikeRebound: a jump when that lifts it at least min_bounce_height, else the slate keeps
/// it and the ball stays on the cloth). Its spin is (r x J) / I with the full
/// 3-D contact point and impulse, so an elevated strike tilts the spin axis and the sliding
/// ball curves (swerve, masse). Side spin squirts the ball away from the side struck by
/// tan(a) = 5/2 b sqrt(1 - b^2) / (1 + m / m_e + 5/2 (1 - b^2)) (TP A.31), b the side offset
/// and m_e the cue's end mass (physics.cue_end_mass, 0 for none).
Strike cueStrike(const Shot& shot, double mass, const PhysicsParams& p);

/// The stroke played on a ball whose centre is at `at`, as both engines play it at time t: the
/// ball's state after, or nothing for a miscue (the tip beyond physics.miscue_limit, or a scoop).
/// A Miscue event, or an Airborne one for a ball the stroke lifts, goes to `events`.
std::optional<Kinematics> strokeBall(int id, double t, Vec2 at, const Shot& shot, double mass,
                                     const PhysicsParams& p, std::vector<Event>& events);

/// The squirt angle (rad, positive to the left of the cue) for a side offset b (fraction of
/// R, positive to the right) of a ball of `mass` struck by a cue of end mass `end_mass`.
double squirtAngle(double b, double mass, double end_mass);

}  // namespace nineball::physics
