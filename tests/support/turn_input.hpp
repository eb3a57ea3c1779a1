#pragma once

#include "nineball/match.hpp"

namespace nineball::test {

/// A plain stroke as a turn: heading (rad) and speed (m/s), the tip centred and the cue level.
inline TurnInput strokeTurn(double heading_rad, double speed) {
  TurnInput t;
  t.shot.heading_rad = heading_rad;
  t.shot.speed = speed;
  return t;
}

}  // namespace nineball::test
