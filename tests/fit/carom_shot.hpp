#pragma once

#include "nineball/sim.hpp"

namespace nineball::testing {

/// A three-cushion shot on a carom match table (reference engine): the cue ball at (-0.6,
/// -0.25), the first object ball near enough to be met while the cue ball still slides (so that
/// the tip shows in what follows: a rolling cue ball keeps only v0 (1 + height) of it), the
/// other at (0.9, 0.45).
inline Scene caromShot(double heading_deg, double speed, Vec2 tip = {}) {
  Scene s;
  s.table = TableDef::carom();
  s.physics = PhysicsParams::carom();
  s.step.engine = EngineKind::named("reference");
  s.balls = {BallState::at(0, {-0.6, -0.25}), BallState::at(1, {-0.15, -0.1}),
             BallState::at(2, {0.9, 0.45})};
  Shot shot;
  shot.heading_rad = heading_deg * kPi / 180.0;
  shot.speed = speed;
  shot.tip = tip;
  s.shot = shot;
  return s;
}

}  // namespace nineball::testing
