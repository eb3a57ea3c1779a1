#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>

namespace nineball::app {

/// Options of `nineball bench`.
struct BenchOptions {
  int repeats = 7;       ///< timed breaks per setting; the median is reported
  bool quick = false;    ///< the default setting and the baseline only
  std::string csv_path;  ///< also write the table as CSV here
  std::string svg_path;  ///< also plot error against run time here (SVG)
};

/// Registers `bench` on the app.
CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options);

/// Sweeps the solver settings (step rate, velocity iterations, scale k, contact model, the
/// baseline): for each, the worst error of every canonical case against its formula and of
/// the whole-shot suite against the reference engine, and the median wall time of a break to
/// rest; marks the Pareto front; compares the default with the plain fixed-rate baseline, spin
/// with no spin, the reference engine's own break time, and rack gaps.
int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err);

}  // namespace nineball::app
