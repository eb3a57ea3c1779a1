#pragma once

#include <CLI/CLI.hpp>
#include <vector>

#include "app/game_options.hpp"

namespace nineball::app {

/// Registers the game window's options on the main command (no subcommand: the game) and
/// returns them, so that a subcommand given with them can be refused.
std::vector<CLI::Option*> addGameOptions(CLI::App& app, GameOptions& options);

}  // namespace nineball::app
