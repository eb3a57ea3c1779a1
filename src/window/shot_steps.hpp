#pragma once

#include <cstddef>
#include <vector>

#include "audio/impact.hpp"
#include "nineball/match.hpp"

namespace nineball::window {

/// A shot's world stepped for the window: the last two states (a frame draws between them) and
/// how many of the world's events have been heard.
struct ShotSteps {
  std::vector<BallState> previous;
  std::vector<BallState> current;
  double previous_time = 0.0;  ///< the world's time at `previous` (s)
  double current_time = 0.0;   ///< and at `current`
  std::size_t events_heard = 0;
  double start = 0.0;  ///< the world's time when the shot began (s)

  /// Starts following the shot `match` has just begun.
  void begin(const Match& match);
  /// Takes up to `steps` fixed steps, adding the sounds of new events to `impacts`; true (and
  /// no more steps) once every ball rests or the shot has run as long as the match lets a shot
  /// run (its physics' max_time: the same cut as headless).
  bool take(Match& match, int steps, std::vector<audio::Impact>& impacts);
  /// The balls a frame `alpha` (0 to 1) of a step past the last state should draw: centres
  /// on the chord, velocities and spins in between (the cloth changes them at a steady rate
  /// within a phase, so a frame between two events has the physics' own).
  std::vector<BallState> between(double alpha) const;
  /// The world's time at that frame.
  double timeBetween(double alpha) const;
};

}  // namespace nineball::window
