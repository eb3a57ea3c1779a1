#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>

#include "accuracy/stress.hpp"

namespace nineball::app {

/// Options of `nineball stress`.
struct StressCommandOptions {
  StressOptions stress;
  std::string contacts = "pairwise";
};

/// Registers `stress` on the app.
CLI::App* addStressCommand(CLI::App& app, StressCommandOptions& options);

/// Runs the numerical stability stress and prints what it tried and how many checks failed.
/// Exit status 0 when nothing failed, 1 otherwise.
int runStressCommand(const StressCommandOptions& options, std::ostream& out);

}  // namespace nineball::app
