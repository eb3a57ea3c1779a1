#pragma once

#include <iosfwd>

#include "app/ai_bench_command.hpp"

namespace nineball::app {

/// `ai-bench` for snooker: `racks` whole frames between two players of the level, the same
/// player breaking off every frame. Reports the mean break (over the visits that scored), the
/// highest break, the frames won by the player who broke off, the century breaks (and per 100
/// frames) and the think time; with `json` one object {"game", "level", "frames", "mean_break",
/// "high_break", "centuries", "think_s": {"median", "max"}}, `centuries` the number of breaks
/// of 100 or more in those frames.
int runSnookerBench(const AiBenchOptions& options, std::ostream& out, std::ostream& err);

}  // namespace nineball::app
