#include "app/break_command.hpp"

#include <charconv>
#include <cstdio>
#include <ostream>

#include "app/cli_checks.hpp"
#include "app/exit_codes.hpp"
#include "common/limits.hpp"
#include "io/result_json.hpp"
#include "nineball/games.hpp"
#include "nineball/scenes.hpp"

namespace nineball::app {
namespace {

std::string format(const char* fmt, double a, double b = 0.0) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, fmt, a, b);
  return buffer;
}

// CLI::Range lets NaN through (every comparison with it is false), so the test is spelled out.
const CLI::Validator kSpeedRange(
    [](std::string& value) -> std::string {
      double v = 0.0;
      if (CLI::detail::lexical_cast(value, v) && v >= 0.0 && v <= limits::kMaxSpeed) return {};
      return "must be a number of m/s from 0 to " + format("%g", limits::kMaxSpeed) +
             " (every speed's limit), found " + value;
    },
    "0..14");

}  // namespace

CLI::App* addBreakCommand(CLI::App& app, BreakOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "break", (std::string("Simulate the standard ") + defaultGame().name + " break headless"));
  cmd->add_option("--seed", options.seed, "Seed of the rack order of balls 2-8")
      ->check(seedCheck())
      ->capture_default_str();
  cmd->add_option("--speed", options.speed, "Cue ball speed in m/s")
      ->check(kSpeedRange)
      ->capture_default_str();
  cmd->add_flag("--json", options.json, "Print the result JSON instead of a summary");
  return cmd;
}

std::string breakSummary(const BreakOptions& options, const SimResult& result) {
  std::string s = "Break (seed " + std::to_string(options.seed) + ", " +
                  format("%g m/s", options.speed) + ")\n";
  std::string pocketed;
  const BallState* cue = nullptr;
  for (const BallState& b : result.balls) {
    if (b.id == kCueBall) cue = &b;
    if (b.pocket && b.id != kCueBall) {
      pocketed += (pocketed.empty() ? "" : ", ") + std::to_string(b.id) + " (" +
                  pocketName(*b.pocket) + ")";
    }
  }
  s += "Pocketed: " + (pocketed.empty() ? std::string("none") : pocketed) + "\n";
  if (!cue) {
    s += "Cue ball: none\n";
  } else if (cue->pocket) {
    s += std::string("Cue ball: pocketed in ") + pocketName(*cue->pocket) + " (scratch)\n";
  } else {
    s += "Cue ball: at " + format("x = %.3f m, y = %.3f m", cue->pos.x, cue->pos.y) + "\n";
  }
  s += "Simulated " + format("%.3f s", result.time) + " in " + std::to_string(result.steps) +
       " steps (" + format("%.1f ms", result.wall_ms) + ")\n";
  return s;
}

int runBreak(const BreakOptions& options, std::ostream& out, std::ostream& err) {
  const Scene scene = breakScene(options.seed, options.speed);
  if (auto problem = validateScene(scene)) {
    err << "nineball break: internal error: the break scene is invalid: " << *problem << '\n';
    return kExitInternal;
  }
  const SimResult result = simulate(scene);
  if (const auto fault = resultFault(scene, result)) {
    err << "nineball break: internal error: " << *fault << '\n';
    return kExitInternal;
  }
  if (options.json) {
    io::writeResult(out, result, true);
    out << '\n';
  } else {
    out << breakSummary(options, result);
  }
  out << std::flush;
  return out ? kExitOk : kExitInternal;
}

}  // namespace nineball::app
