#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>

namespace nineball::app {

/// Options of `nineball sim`.
struct SimOptions {
  std::string scene_path;  ///< a file, or "-" for standard input
};

/// Registers `sim SCENE` on the app; the options are filled in when the command line is parsed.
CLI::App* addSimCommand(CLI::App& app, SimOptions& options);

/// Reads the scene, simulates it and prints the result JSON on `out`. A bad scene prints
/// "nineball sim: <file>: <reason>" on `err`, nothing on `out`, and returns kExitBadInput.
int runSim(const SimOptions& options, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace nineball::app
