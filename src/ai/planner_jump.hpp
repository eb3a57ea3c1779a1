#pragma once

#include <vector>

#include "nineball/ball.hpp"
#include "nineball/params.hpp"
#include "nineball/vec2.hpp"

// Jump shots: the strokes that lift the cue ball over the balls in its way, from the flight's
// closed form (docs/physics.md, "Balls in the air"), before any simulation.
namespace nineball::ai {

/// A jump stroke: the cue's elevation and the speed along it, and where the ball first comes
/// down, m along the heading from where it is struck.
struct JumpStroke {
  double elevation_rad = 0.0;
  double speed = 0.0;
  double lands_at = 0.0;
};

/// The balls (other than the cue ball and `skip`) a ball of radius `radius` rolling from `cue`
/// along `heading` would meet before it has gone `reach` m: those that make a jump worth trying.
std::vector<const BallState*> ballsInTheWay(const std::vector<BallState>& balls, Vec2 cue,
                                            double heading, double reach, double radius, int skip);

/// At each of the planner's elevations, the softest of its jump speeds whose first flight clears
/// every one of `blockers` by kJumpClearance in space, comes down beyond them and no later than
/// `land_by` m along the heading; empty when there is nothing to clear or the cloth lets no ball
/// leave it.
std::vector<JumpStroke> jumpStrokes(const PhysicsParams& p, Vec2 cue, double heading,
                                    const std::vector<const BallState*>& blockers, double land_by);

}  // namespace nineball::ai
