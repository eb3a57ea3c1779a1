#pragma once

#include <iosfwd>

namespace nineball::app {

/// Replaces this process with nineball-game (beside this executable) on the same command
/// line: the headless commands never load SFML, X11 or GL, and the window does only when it
/// opens. Returns (kExitInternal, with a message) only when that program cannot be run.
int launchGameWindow(char** argv, std::ostream& err);

}  // namespace nineball::app
