#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <iosfwd>
#include <string>

#include "nineball/games.hpp"

namespace nineball::app {

/// Options of `nineball ai-bench`.
struct AiBenchOptions {
  std::string level = "master";           ///< the level measured (or an older name)
  std::string game = defaultGame().name;  ///< a game of the registry (nineball/games.hpp)
  int positions = 100;                    ///< seeded practice positions to pot the ball on from
  /// Racks broken to try to run out (carom: games played to the distance; snooker: whole
  /// frames); -1 for the game's default, 100 racks of pool, no carom games or 4 snooker frames.
  int racks = -1;
  std::uint64_t seed = 1;  ///< first seed of the positions and the racks
  int threads = 2;         ///< workers simulating candidates
  /// "level" (the level's own cueing errors) or a name of ai::ExecutionNoise::names ("none",
  /// "olympiad": the computer-pool tournaments' noise, "olympiad-5x") in place of the level's.
  std::string noise = "level";
  bool json = false;  ///< one JSON object on stdout instead of the report
  /// "A,B": instead of the level's racks, `racks` whole racks between levels A and B, the
  /// break alternating (A breaks the first).
  std::string versus;
};

/// Registers `ai-bench` on the app.
CLI::App* addAiBenchCommand(CLI::App& app, AiBenchOptions& options);

/// Measures the computer opponent: how often it pots the ball on from seeded positions, how
/// many racks it runs out from its own break, how many shots its search simulates per second
/// and how long it thinks per shot. Prints a short report on `out`, or with `json` one object:
/// {"game", "level", "noise", "positions": {"made", "fouls", "of"}, "racks": {"runouts", "of",
/// "ball_down_on_break"}, "shots": {"succeeded", "attempted"}, "think_s": {"median", "max"},
/// "shots_simulated_per_cpu_s"}; with `versus` also "versus": {"A", "B", "racks", "wins":
/// {"A", "B"}}. Carom (ai_bench_carom.hpp) and snooker (ai_bench_snooker.hpp) report their own.
int runAiBench(const AiBenchOptions& options, std::ostream& out, std::ostream& err);

}  // namespace nineball::app
