#pragma once

#include "nineball/params.hpp"
#include "physics/model/motion.hpp"
#include "physics/resolve/cushion/registry.hpp"

namespace nineball::physics {

/// A ball's rebound from a cushion whose nose stands above its centre (Mathavan, Jackson and
/// Parkin, Proc. IMechE C 224, 2010). The contact I on the nose is at sin(theta) =
/// (cushion_height - R) / R above the centre, so the impulse there also presses the ball into
/// the slate, and friction acts at both contacts during the impact: at I with
/// cushion_friction, at the slate C with sliding_friction, each against its own slip.
/// The equations of motion are integrated over the normal impulse P at I: compression until
/// the ball no longer moves into the cushion, then restitution until the normal force has
/// given back cushion_restitution^2 of the work it took. Topspin, draw and side spin all
/// change the rebound. Every velocity scales with the approach speed (the model is rigid and
/// impulsive), so the rebound is the same at every speed.
/// `inward` is the cushion's normal, into the table; `impulse` is the total P, integrated in
/// 100 midpoint steps a phase.
Kinematics mathavanBounce(Kinematics k, Vec2 inward, double mass, const PhysicsParams& p,
                          double& impulse);

/// The same rebound integrated in `steps` midpoint steps a phase (the same regularisation):
/// the yardstick mathavanBounce is held to (20,000 steps).
Kinematics mathavanBounceInSteps(Kinematics k, Vec2 inward, double mass, const PhysicsParams& p,
                                 int steps, double& impulse);

/// "mathavan": mathavanBounce, reading cushion_height, which must stand between the ball's
/// centre and its top.
CushionModelDef mathavan2010Cushion();

}  // namespace nineball::physics
