#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>

namespace nineball::app {

/// Options of `nineball match`.
struct MatchOptions {
  std::string script_path;  ///< a file, or "-" for standard input
};

/// Registers `match SCRIPT` on the app.
CLI::App* addMatchCommand(CLI::App& app, MatchOptions& options);

/// Plays the script's rack and prints one JSON result on `out`: a computer player's turns are
/// planned, a human's come from the script in order; it stops when the rack is won, when a
/// human is to play and the script has no turn left, or after 500 turns. A bad script or an
/// illegal action prints "nineball match: <file>: <reason>" on `err`, nothing on `out`, and
/// returns kExitBadInput.
int runMatch(const MatchOptions& options, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace nineball::app
