#pragma once

#include <cstdint>
#include <vector>

#include "app/ai_bench_command.hpp"
#include "nineball/planner.hpp"

namespace nineball::app {

/// A planner of the level for ai-bench, cueing with the noise `o.noise` names instead of the
/// level's own when it names one.
ai::Planner benchPlanner(const AiBenchOptions& o, ai::Level level, std::uint64_t seed);

/// The median of the values (0 for none).
double medianOf(std::vector<double> v);

}  // namespace nineball::app
