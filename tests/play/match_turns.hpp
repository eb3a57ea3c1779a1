// Turns of a match as the play tests write them: a shot at a heading (degrees) and speed, the
// answer to a decision, and where a ball stands after them.
#pragma once

#include <gtest/gtest.h>

#include <optional>

#include "nineball/match.hpp"

namespace nineball::play_test {

/// A shot at `heading_deg` and `speed` m/s, placing the cue ball at `cue` when given.
inline TurnInput shot(double heading_deg, double speed, std::optional<Vec2> cue = std::nullopt) {
  TurnInput t;
  t.shot = Shot::withSpeed(heading_deg, speed);
  t.cue = cue;
  return t;
}

/// The answer to a decision: shoot from there (true) or pass; snooker's replace after a miss.
inline TurnInput decision(bool shoot, bool replace = false) {
  TurnInput t;
  t.kind = TurnInput::Kind::Decision;
  t.shoot = shoot;
  t.replace = replace;
  return t;
}

/// Where ball `id` stands (a test failure when the match has no such ball).
inline Vec2 where(const Match& m, int id) {
  for (const BallState& b : m.balls()) {
    if (b.id == id) return b.pos;
  }
  ADD_FAILURE() << "no ball " << id;
  return {};
}

}  // namespace nineball::play_test
