// Shots of the game's session played to their end the way the window plays them.
#pragma once

#include <cmath>

#include "window/game_session.hpp"

namespace nineball::window {

/// Where a ball dropping into pocket `id` of the session's table goes (its drop centre).
inline Vec2 pocketCentre(const GameSession& s, PocketId id) {
  for (const Pocket& p : s.match().world().table().pockets) {
    if (p.id == id) return p.drop_centre;
  }
  return {};
}

/// Runs the shot to its end a `frame` (s) at a time, 60 a second unless told; false if it has
/// not ended after two minutes.
inline bool roll(GameSession& s, double frame_s = 1.0 / 60.0) {
  const long frames = std::lround(120.0 / frame_s);
  for (long frame = 0; frame < frames; ++frame) {
    s.advance(frame_s);
    if (s.phase() != Phase::Rolling) return true;
  }
  return false;
}

}  // namespace nineball::window
