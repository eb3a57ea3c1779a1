#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <iosfwd>
#include <string>

#include "nineball/sim.hpp"

namespace nineball::app {

/// Options of `nineball break` (and of a bare `nineball`, which runs the default break).
struct BreakOptions {
  std::uint64_t seed = 1;  ///< rack order of balls 2-8
  double speed = 10.0;     ///< m/s of the cue ball
  bool json = false;       ///< print the result JSON instead of the summary
};

/// Registers `break [--seed N] [--speed V] [--json]` on the app.
CLI::App* addBreakCommand(CLI::App& app, BreakOptions& options);

/// Simulates the standard break headless and prints a summary (or the result JSON) on `out`.
int runBreak(const BreakOptions& options, std::ostream& out, std::ostream& err);

/// A few lines for people: balls pocketed, where the cue ball ended, time and steps.
std::string breakSummary(const BreakOptions& options, const SimResult& result);

}  // namespace nineball::app
