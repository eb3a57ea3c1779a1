#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "nineball/params.hpp"
#include "nineball/table.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

/// Two balls meeting with centres along a -> b: the paper's oblique collision (normal part by
/// the 1-D restitution law, tangential part kept). When they part slower than a ball can
/// bounce, spin that would press them together again is stopped: else they would meet in an
/// endless run of ever smaller bounces. Positions and the rest of the spin are kept.
void collideBalls(Kinematics& a, Kinematics& b, double mass_a, double mass_b,
                  const PhysicsParams& p);

/// Balls the cloth presses together (a perfectly inelastic pair, the one behind with more
/// topspin) are met again each time they overlap by the touch tolerance, and set back to
/// touching here: each moved half the overlap along the normal, except one that the move
/// would sink into a cushion. Micrometres of position, no velocity: no energy.
void setApart(Kinematics& a, Kinematics& b, const TableGeometry& table, double r);

}  // namespace nineball::physics
