#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>

namespace nineball::app {

/// Options of `nineball bench`.
struct BenchOptions {
  int repeats = 7;       ///< timed breaks per setting; the median is reported
  bool quick = false;    ///< the default setting only
  std::string csv_path;  ///< also write the table as CSV here
};

/// Registers `bench` on the app.
CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options);

/// Sweeps the solver settings (scale k, step rate, contact model): for each, the worst error
/// of every canonical case against its formula and the median wall time of a break to rest.
int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err);

}  // namespace nineball::app
