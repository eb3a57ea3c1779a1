#pragma once

#include <string>
#include <vector>

#include "nineball/rules.hpp"

namespace nineball::window {

/// The help screen's first lines: the mouse and the keys.
std::vector<std::string> controlHelpLines();

/// The help screen's last lines: the game's rules in brief, and how to call a shot.
std::vector<std::string> gameHelpLines(rules::Game game);

/// A player's group as the HUD shows it: "solids", "stripes" or "open table".
std::string groupLabel(const rules::Groups& groups, rules::Player player);

}  // namespace nineball::window
