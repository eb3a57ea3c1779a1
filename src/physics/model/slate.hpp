#pragma once

#include "nineball/params.hpp"
#include "physics/model/motion.hpp"

// The slate under a ball in the air: when it lands, how it bounces (docs/physics.md, "Balls in
// the air"). Heights are of the ball's centre above where it rests on the cloth.
namespace nineball::physics {

/// True when the physics lets a ball leave the cloth: the spin cloth (the real models). The
/// paper's cloths carry no spin or run on a damped clock in which a parabola is no polynomial;
/// on them the slate takes every vertical impulse, as it always did.
bool airborneAllowed(const PhysicsParams& p);

/// s until a ball at height z >= 0 moving up at vz meets the slate:
/// (vz + sqrt(vz^2 + 2 g z)) / g, in a form without cancellation for a falling ball.
double landingTime(double z, double vz, double g);

/// How high the bottom of a ball leaving the slate at vz rises above it: vz^2 / 2g.
double bounceHeight(double vz, double g);

/// A ball meeting the slate at vz < 0 (a frictional, inelastic bounce; Alciatore, TP A.14, as
/// pooltool's ball-table model): the vertical speed comes back times table_restitution, and the
/// slate's friction (sliding_friction) acts on the contact point's slip with the normal impulse,
/// up to the impulse that ends the slip; a rebound that would lift the ball less than
/// min_bounce_height leaves it on the cloth. A ball not moving into the slate is returned as it
/// is.
Kinematics bounceOffSlate(Kinematics k, const PhysicsParams& p);

/// The slate's answer to a cue driving the ball into it at vz < 0: the vertical speed back
/// times table_restitution, when that lifts the ball at least min_bounce_height; else none (the
/// ball stays on the cloth, the slate having taken the stroke's vertical part). The slate's
/// friction during the stroke is not modelled (docs/physics.md).
double strikeRebound(double vz, const PhysicsParams& p);

/// Kinetic energy, rotation included, and the height's potential energy (J).
double mechanicalEnergy(const Kinematics& k, double mass, double radius, double g);

}  // namespace nineball::physics
