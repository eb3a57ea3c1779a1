// Shots of the game's session played to their end the way the window plays them.
#pragma once

#include "window/game_session.hpp"

namespace nineball::window {

/// Runs the shot to its end at 60 frames per second; false if it never ends.
inline bool roll(GameSession& s) {
  for (int frame = 0; frame < 60 * 120; ++frame) {
    s.advance(1.0 / 60.0);
    if (s.phase() != Phase::Rolling) return true;
  }
  return false;
}

}  // namespace nineball::window
