#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>

namespace nineball::app {

/// Options of `nineball plan`.
struct PlanOptions {
  std::string scene_path;  ///< a file, or "-" for standard input
};

/// Registers `plan SCENE` on the app.
CLI::App* addPlanCommand(CLI::App& app, PlanOptions& options);

/// Reads the position, asks the computer opponent for its shot and prints it as JSON on `out`.
/// A bad scene prints "nineball plan: <file>: <reason>" on `err`, nothing on `out`, and
/// returns kExitBadInput.
int runPlan(const PlanOptions& options, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace nineball::app
