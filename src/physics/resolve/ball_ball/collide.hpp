#pragma once

#include <optional>

#include "nineball/vec2.hpp"

namespace nineball::physics {

/// Centres this much (m) farther apart than touching still count as touching: Box2D keeps
/// positions in single precision, so two balls set touching read back a little apart.
constexpr double kTouchTolerance = 1e-6;

/// Balls closing slower than this (m/s) are taken as resting against each other: after a
/// perfectly inelastic contact the rounding of single precision must not start another.
constexpr double kMinClosingSpeed = 1e-4;

/// Velocities of two balls after an instantaneous frictionless collision.
struct CollisionOutcome {
  Vec2 v1;
  Vec2 v2;
};

/// The paper's oblique collision (eq. 2.14-2.65): along the unit normal n (from ball 1 to
/// ball 2) the 1-D restitution formulas with masses m1, m2 and coefficient e; the tangential
/// parts are kept.
CollisionOutcome collide(Vec2 u1, Vec2 u2, double m1, double m2, double e, Vec2 n);

}  // namespace nineball::physics
