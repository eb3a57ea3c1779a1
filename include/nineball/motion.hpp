#pragma once

#include <optional>

#include "nineball/ball.hpp"
#include "nineball/params.hpp"
#include "nineball/trace.hpp"

/// A ball's free motion on the cloth, by the closed forms both engines follow between events
/// (sliding, rolling, spinning in place, at rest): for studying the cloth model on its own, no
/// table, cushions or other balls.
namespace nineball {

/// Where `ball` is and how it moves `t` seconds (>= 0) later, crossing from one phase to the
/// next as the cloth model of `p` says (a sliding ball starts rolling, a rolling one stops).
BallState freeMotion(const BallState& ball, double t, const PhysicsParams& p);

/// What the cloth of `p` is doing to a ball moving freely in state `ball` (never Pocketed):
/// the phase a trace names.
TracePhase freePhase(const BallState& ball, const PhysicsParams& p);

/// A traced ball (a trace of a run of these physics) at time t, at or after its first sample:
/// its last sample at or before t carried on by freeMotion. Every event's instant is a sample,
/// so no event lies between: this is the run's own motion, not an interpolation. A pocketed
/// ball stays where it dropped.
BallState tracedState(const BallTrace& b, double t, const PhysicsParams& p);

/// The first instant within `horizon` seconds (finite, >= 0) at which two balls moving freely
/// (as freeMotion moves them) touch while closing, or nothing: the contact time the engines
/// solve for (a quartic while either slides or rolls).
std::optional<double> timeToTouch(const BallState& a, const BallState& b, const PhysicsParams& p,
                                  double horizon);

}  // namespace nineball
