#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nineball/params.hpp"
#include "nineball/table.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

/// Below this normal speed (m/s) a contact is resting, not a bounce: Box2D applies no
/// restitution under it either (its restitution threshold is set to the same value).
constexpr double kRestingSpeed = 1e-4;

/// A perfectly inelastic stop against every face in `normals` at once: the velocity nearest
/// to today's that enters none of them (in a wedge, often none at all). Pair by pair the
/// same stop only creeps towards it, by a factor of the wedge's angle each time.
/// `impulse` is the size of the impulse given.
Kinematics stopAgainst(Kinematics k, const std::vector<Vec2>& normals, double mass,
                       double& impulse);

/// A ball that rests against an obstacle (normal speed under kRestingSpeed) while its own
/// slip drives it into it: the obstacle takes the part of the spin that presses, so that the
/// ball slides along it instead of bouncing against it ever more often (a Zeno sequence).
/// `towards` is the unit vector from the ball to the obstacle. Never adds energy.
Kinematics stopPressing(Kinematics k, Vec2 towards, const PhysicsParams& p);

/// A ball pressed into a cushion (by other balls, or by a contact met a little late) is met
/// again once it sinks by the touch tolerance, and set back out along the cushion's normal
/// here: micrometres of position, no velocity, so no energy.
void setOutOfCushion(Kinematics& k, Vec2 normal, const TableGeometry& table, double r);

/// True when a cushion contact is no bounce, only a touch: met with no speed into the cushion
/// (at most kMinClosingSpeed), or at the end of a rail face the ball runs along (among
/// `faces`, those it touches; the contact's normal within the touch tolerance of that face's):
/// a ball rolling along a rail past a jaw point, a path tangent to a cushion, a ball crawling
/// along a rail and pressed into it by its spin or by rounding. Neither engine bounces it or
/// records an event (a ball frozen to a rail does not "reach a rail"): it is only kept out of
/// the cushion (restAgainstCushion).
bool touchesOnly(const Kinematics& k, Vec2 normal, const std::vector<Vec2>& faces, double r);

/// A ball that only touches a cushion: any crawl into it stopped, the pressing spin taken
/// away, and the ball set back out if pressed in. Never adds energy.
Kinematics restAgainstCushion(Kinematics k, Vec2 normal, const TableGeometry& table,
                              const PhysicsParams& p);

/// Why a cushion whose nose is the contact point (`model`, as the message names it: "the
/// Mathavan cushion") cannot run with `p`: the nose must stand no lower than the ball's centre
/// (there the impulse is level; lower, it would lift the ball) and below its top (above, it
/// misses the ball). One range for every such model.
std::optional<std::string> noseHeightFault(const PhysicsParams& p, const char* model);

}  // namespace nineball::physics
