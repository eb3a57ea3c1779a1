#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <iosfwd>
#include <string>

#include "nineball/json.hpp"

namespace nineball::app {

/// Options of `nineball fit`.
struct FitCommandOptions {
  std::string path;  ///< recorded shots: a file, or "-" for standard input
  int evals = 12000;
  std::string objective = "full";
  std::uint64_t seed = 1;
  int threads = 0;
};

/// Options of `nineball calibrate`.
struct CalibrateCommandOptions {
  std::string path;
  std::string params;  ///< comma-separated physics parameters
  CalibrateRequest settings;  ///< all but the parameters, which come from `params`
};

CLI::App* addFitCommand(CLI::App& app, FitCommandOptions& options);
CLI::App* addCalibrateCommand(CLI::App& app, CalibrateCommandOptions& options);

/// Fits every recorded shot and prints one JSON line each, in the input's order (docs/cli.md).
/// Bad input: a message on `err`, nothing on `out`, kExitBadInput.
int runFit(const FitCommandOptions& options, std::istream& in, std::ostream& out,
           std::ostream& err);

/// Calibrates the named physics parameters and prints one JSON object (docs/cli.md).
int runCalibrate(const CalibrateCommandOptions& options, std::istream& in, std::ostream& out,
                 std::ostream& err);

}  // namespace nineball::app
