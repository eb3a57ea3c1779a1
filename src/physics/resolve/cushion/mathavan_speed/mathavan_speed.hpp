#pragma once

#include "nineball/params.hpp"
#include "physics/model/motion.hpp"
#include "physics/resolve/cushion/registry.hpp"

namespace nineball::physics {

/// The restitution the speed-dependent cushion gives a ball reaching it at normal speed
/// `speed` (m/s): e(V) = cushion_restitution_base + cushion_restitution_slope V +
/// cushion_restitution_quadratic V^2, held within [cushion_restitution_min, 1]. With the
/// defaults, Han 2005's fit to measured rebounds (J. Mech. Sci. Tech. 19, his eq. 26).
double speedRestitution(double speed, const PhysicsParams& p);

/// Mathavan et al. 2010's rebound (mathavanBounce) with a restitution that depends on the
/// normal approach speed: the model's own coefficient (the share of the work given back) is
/// set for each impact so that a ball without spin, straight in at this normal speed, leaves
/// at speedRestitution(V) of it, the ratio the measurement gives. A ball whose rebound would
/// need a coefficient above 1 gets 1 (the cushion cannot give back more than it took).
Kinematics mathavanSpeedBounce(Kinematics k, Vec2 inward, double mass, const PhysicsParams& p,
                               double& impulse);

/// The coefficient of Mathavan's model that gives a ball without spin, straight in, the
/// rebound ratio `target` (at most 1).
double mathavanCoefficientFor(double target, double mass, const PhysicsParams& p);

/// "mathavan_speed": mathavanSpeedBounce, reading cushion_height and the four
/// cushion_restitution_* fields, not cushion_restitution.
CushionModelDef mathavanSpeedCushion();

}  // namespace nineball::physics
