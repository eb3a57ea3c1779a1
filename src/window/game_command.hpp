#pragma once

#include <iosfwd>

#include "app/game_options.hpp"

namespace nineball::window {

/// Starts the game window: reads the --script if any (a bad one is refused like
/// `nineball match` refuses it, status 2), then runs the window.
int runGameCommand(const app::GameOptions& options, std::istream& in, std::ostream& err);

}  // namespace nineball::window
