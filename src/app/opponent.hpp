#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nineball/planner.hpp"

namespace nineball::app {

/// Who plays Player 2's seat: a second person at the same computer (nothing), or the
/// computer at a level.
using Opponent = std::optional<ai::Level>;

/// "human", "ai:easy", "ai:medium", "ai:hard": the names of the --opponent option.
std::string opponentName(const Opponent& opponent);
/// Reads an --opponent name; nothing for an unknown one.
std::optional<Opponent> opponentFromName(const std::string& name);
/// Every --opponent name, in the order the O key cycles through them.
std::vector<std::string> opponentNames();
/// What the HUD calls the mode: "2 players", "vs computer (medium)".
std::string opponentLabel(const Opponent& opponent);
/// The next mode of the O key: 2 players, then easy, medium, hard, and round again.
Opponent nextOpponent(const Opponent& opponent);

}  // namespace nineball::app
