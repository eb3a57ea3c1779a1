#pragma once

#include <iosfwd>

#include "app/ai_bench_command.hpp"

namespace nineball::app {

/// `ai-bench` for a carom game: the level plays one inning from each of `positions` seeded
/// positions (even ones the opening position, odd ones three balls at random), and with
/// `racks` that many games to the game's distance between two players of the level from the
/// opening position. Reports points per inning (the average), the high run and the think time;
/// with `json` one object {"game", "level", "points", "innings", "average", "high_run",
/// "think_s": {"median", "max"}} over every inning played.
int runCaromBench(const AiBenchOptions& options, std::ostream& out, std::ostream& err);

}  // namespace nineball::app
