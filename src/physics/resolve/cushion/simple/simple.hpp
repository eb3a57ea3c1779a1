#pragma once

#include "nineball/params.hpp"
#include "physics/model/motion.hpp"
#include "physics/resolve/cushion/registry.hpp"

namespace nineball::physics {

/// The paper's cushion (section 7): the normal part of the velocity reversed and scaled by
/// cushion_restitution, the tangential part kept. `normal` is the unit normal from the
/// cushion to the ball. Returns the normal impulse the cushion gave (kg m/s) in `impulse`.
Kinematics bounceOffCushion(Kinematics k, Vec2 normal, double mass, const PhysicsParams& p,
                            double& impulse);

/// Friction at the cushion nose (spin cloth only): it acts on the slip of the contact point,
/// Coulomb with cushion_friction times the normal impulse, capped where the point stops
/// slipping; side spin changes the angle off the rail, and the rail changes the side spin.
Kinematics cushionFriction(Kinematics k, Vec2 normal, double normal_impulse, double mass,
                           const PhysicsParams& p);

/// "simple": the paper's restitution law with Coulomb friction at the nose.
CushionModelDef simpleCushion();

}  // namespace nineball::physics
