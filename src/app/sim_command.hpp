#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <optional>
#include <string>

#include "nineball/sim.hpp"

namespace nineball::app {

/// Options of `nineball sim`.
struct SimOptions {
  std::string scene_path;               ///< a file, or "-" for standard input
  bool jsonl = false;                   ///< one scene per line in, one result per line out
  std::optional<std::string> svg_path;  ///< also draw the shot into this SVG file
};

/// JSON cannot hold NaN or infinity (nlohmann would print null), so such a result is a bug.
bool allFinite(const SimResult& r);

/// The line on stderr for a trace cut at limits::kMaxTraceSamples.
std::string traceTruncatedNote(const Trace& trace);

/// Registers `sim SCENE` on the app; the options are filled in when the command line is parsed.
CLI::App* addSimCommand(CLI::App& app, SimOptions& options);

/// Reads the scene, simulates it and prints the result JSON on `out` (and with --svg draws the
/// shot into that file first). A bad scene, or an --svg file that cannot be written, prints
/// "nineball sim: <file>: <reason>" on `err`, nothing on `out`, and returns kExitBadInput.
int runSim(const SimOptions& options, std::istream& in, std::ostream& out, std::ostream& err);

/// `sim --jsonl`: every non-blank line of the input is a scene; each gets one line on `out`,
/// its result as compact JSON or {"error": "...", "line": N}, and the rest go on. Returns
/// kExitBadInput when any line was refused (or the input could not be read), else
/// kExitPartial when any result is partial, else kExitOk.
int runSimLines(const SimOptions& options, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace nineball::app
