#pragma once

#include <string>
#include <vector>

#include "nineball/seat.hpp"

namespace nineball::app {

// Player 2's seat in the game window (the --opponent option, the O key): a second person at
// the same computer, or the computer at a level. Its names are the seat's (seatName).

/// Every --opponent name, in the order the O key cycles through them.
std::vector<std::string> opponentNames();
/// What the HUD calls the mode: "2 players", "vs computer (medium)".
std::string opponentLabel(const Seat& opponent);
/// The next mode of the O key: 2 players, then each level from beginner to master, and round again.
Seat nextOpponent(const Seat& opponent);

}  // namespace nineball::app
