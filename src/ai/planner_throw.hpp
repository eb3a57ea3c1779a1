#pragma once

#include <optional>

#include "nineball/params.hpp"
#include "nineball/shot.hpp"
#include "nineball/vec2.hpp"

// Aim that allows for what the ghost ball leaves out: the cue ball squirts off its line with
// side spin, and ball-ball friction throws the object ball off the line of centres (by up to
// 5 degrees at a slow cut: a miss at any pocket more than a metre away).
namespace nineball::ai {

/// A cue ball of `cue_mass` at `cue` struck with `shot`, and an object ball of `object_mass` at
/// rest at `object`.
struct ThrowSetup {
  Vec2 cue;
  double cue_mass = 0.0;
  Vec2 object;
  double object_mass = 0.0;
  Shot shot;
};

/// The direction (rad) the object ball leaves in when the cue ball is struck along `heading`:
/// the cue ball's path and spin at the contact from the cloth's closed form, the contact from
/// the ball-ball model the physics uses. Nothing when the cue ball stops short or misses it.
std::optional<double> objectDeparture(const PhysicsParams& p, const ThrowSetup& s, double heading);

/// The heading near `heading` (the ghost ball's) that sends the object ball off along
/// `want_rad`, found by Newton's method on objectDeparture; `heading` itself when no such
/// heading is found within a few degrees.
double headingAllowingForThrow(const PhysicsParams& p, const ThrowSetup& s, double heading,
                               double want_rad);

}  // namespace nineball::ai
