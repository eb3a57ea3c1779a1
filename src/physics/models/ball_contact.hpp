#pragma once

#include "nineball/params.hpp"
#include "physics/motion.hpp"

namespace nineball::physics {

/// Two balls meeting with centres along a -> b: the paper's oblique collision (normal part by
/// the 1-D restitution law, tangential part kept). When they part slower than a ball can
/// bounce, spin that would press them together again is stopped: else they would meet in an
/// endless run of ever smaller bounces. Positions and the rest of the spin are kept.
void collideBalls(Kinematics& a, Kinematics& b, double mass_a, double mass_b,
                  const PhysicsParams& p);

}  // namespace nineball::physics
