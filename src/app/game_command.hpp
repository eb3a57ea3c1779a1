#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <vector>

#include "app/game/game_options.hpp"

namespace nineball::app {

/// Registers the game window's options on the main command (no subcommand: the game) and
/// returns them, so that a subcommand given with them can be refused.
std::vector<CLI::Option*> addGameOptions(CLI::App& app, GameOptions& options);

/// Starts the game window: reads the --script if any (a bad one is refused like
/// `nineball match` refuses it, status 2), then runs the window.
int runGameCommand(const GameOptions& options, std::istream& in, std::ostream& err);

}  // namespace nineball::app
