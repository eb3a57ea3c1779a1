#pragma once

#include "nineball/rules.hpp"

namespace nineball::rules {

/// A player's place in the per-player arrays (score, innings, misses): A 0, B 1.
inline int playerIndex(Player p) {
  return p == Player::A ? 0 : 1;
}

}  // namespace nineball::rules
