#pragma once

#include "nineball/params.hpp"
#include "physics/model/motion.hpp"
#include "physics/resolve/cushion/registry.hpp"

namespace nineball::physics {

/// A ball's rebound from a cushion as a compliant impact with tangential compliance (Stronge,
/// "Impact Mechanics", 2000, ch. 5.2), the model pooltool has used by default since 0.6.0: the
/// contact point on the ball meets the rubber through a normal spring and a tangential one
/// (k_n / k_t = eta^2). The normal spring is stiffened by 1 / e^2 once compression ends, so
/// the normal work given back is cushion_restitution^2 of that taken (the energetic
/// coefficient). The tangential spring lets the contact stick, slip, and reverse its slip, with
/// Coulomb's cushion_friction on the normal force: a ball can leave faster along the rail than
/// a rigid rough cushion would let it (the effect behind twice- and thrice-across banks).
/// The contact is at the nose, sin(theta) = (cushion_height - R) / R above the centre, as in
/// pooltool's 3-D version of the model (0.6.0 put it at the centre's height: cushion_height =
/// R here); its impulse points through the centre. Only the
/// cushion acts during the impact: the slate takes whatever vertical velocity the impulse
/// gives (the ball stays on the table; its friction is not modelled here, unlike Mathavan's),
/// and a ball that would then still move into the cushion (a restitution under about 0.14 on
/// the standard nose) is stopped against it.
/// Spin of every kind changes the slip at the nose and so the rebound, and the friction's
/// impulse changes the spin. Every velocity scales with the approach speed (the springs are
/// linear), so the rebound angles are the same at every speed.
/// `inward` is the cushion's normal, into the table; `impulse` is the total normal impulse
/// at the nose (kg m/s). The position is unchanged.
Kinematics strongeBounce(Kinematics k, Vec2 inward, double mass, const PhysicsParams& p,
                         double& impulse);

/// The tangential part of the same impact alone, in units of the contact's normal approach
/// speed: the contact slips at `slip` when it meets the cushion; returns its slip along the
/// same line when it leaves (of the other sign: reversed). The normal part needs no solving (it
/// leaves at e times the approach speed). `omega_ratio` is omega_t / omega_n of the two
/// springs, in (1, 2); strongeBounce uses 1.8. Exposed for its tests.
double strongeSlipAfter(double slip, double friction, double restitution, double omega_ratio);

/// "stronge": strongeBounce, reading cushion_height, which may stand from the ball's centre
/// (pooltool 0.6.0's contact) up to below its top.
CushionModelDef strongeCompliantCushion();

}  // namespace nineball::physics
