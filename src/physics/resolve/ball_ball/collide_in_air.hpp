#pragma once

#include "nineball/params.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

/// Two balls meeting with one at least in the air (a jump onto a ball, a ball struck above its
/// equator): the impulse acts along the line of their centres in space, with ball_restitution,
/// and without the ball-ball friction of the chosen model (no throw off the cloth: see
/// docs/physics.md, "Balls in the air"). A ball on the cloth driven into the slate bounces off
/// it (bounceOffSlate), and may hop.
void collideInAir(Kinematics& a, Kinematics& b, double mass_a, double mass_b,
                  const PhysicsParams& p);

}  // namespace nineball::physics
