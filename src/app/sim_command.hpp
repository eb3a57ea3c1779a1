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
  std::optional<std::string> png_path;  ///< also draw the shot with the game's renderer
};

/// Draws a traced shot into a PNG with the game's renderer; false with `why` when it cannot.
using ShotPngWriter = bool (*)(const Scene& scene, const SimResult& traced, const std::string& path,
                               std::string& why);
/// The renderer `sim --png` uses. The headless `nineball` has none (it loads no display
/// library) and hands such a command line to nineball-game, which registers one.
void setShotPngWriter(ShotPngWriter writer);
bool haveShotPngWriter();

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
