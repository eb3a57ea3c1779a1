#include "app/stress_command.hpp"

#include <chrono>
#include <cstdio>
#include <ostream>

#include "app/exit_codes.hpp"

namespace nineball::app {

CLI::App* addStressCommand(CLI::App& app, StressCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "stress", "Numerical stability: random and hostile scenes, every step checked");
  StressOptions& s = options.stress;
  cmd->add_option("--seed", s.seed, "Seed of the random layouts")->capture_default_str();
  cmd->add_option("--layouts", s.random_layouts, "Random layouts and shots")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  cmd->add_option("--settings", s.random_settings,
                  "Scenes with table, physics, step rate and scale drawn from their allowed "
                  "ranges (they keep their own step settings)")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  cmd->add_option("--crowd", s.crowded_balls, "Balls on the crowded table")
      ->check(CLI::Range(2, 400))
      ->capture_default_str();
  cmd->add_option("--long-run", s.long_run_s, "Simulated seconds of the endless run")
      ->check(CLI::Range(1.0, 360000.0))
      ->capture_default_str();
  cmd->add_option("--scale", s.step.box2d.scale, "Box2D units per metre")
      ->check(CLI::Range(1.0, 10000.0))
      ->capture_default_str();
  cmd->add_option("--hz", s.step.hz, "Base step rate")
      ->check(CLI::Range(1.0, 100000.0))
      ->capture_default_str();
  cmd->add_option("--only", s.only,
                  "Run only the scenarios whose names start with this (as \"settings #616 \" "
                  "in a failure's description); may be given again");
  cmd->add_option("--contacts", options.contacts, "pairwise or box2d")
      ->check(CLI::IsMember({"pairwise", "box2d"}))
      ->capture_default_str();
  return cmd;
}

int runStressCommand(const StressCommandOptions& options, std::ostream& out) {
  StressOptions o = options.stress;
  o.step.box2d.contacts = *contactModelFromName(options.contacts);
  const auto start = std::chrono::steady_clock::now();
  const StressReport r = runStress(o);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out << "stress (seed " << o.seed << ", " << contactModelName(o.step.box2d.contacts)
      << " k=" << o.step.box2d.scale << " " << o.step.hz << " Hz), each scenario run twice:\n";
  for (const auto& [kind, count] : r.scenarios) out << "  " << count << " x " << kind << '\n';
  out << "  each also through the reference engine (" << r.reference_runs << " scenarios)\n";
  char line[256];
  std::snprintf(line, sizeof line,
                "%ld steps, %.0f s simulated, %ld checks in %.1f s of wall time: %ld failed\n",
                r.steps, r.simulated_s, r.checks, wall, r.failureCount());
  out << line;
  for (const auto& [what, count] : r.failures) out << "  " << what << ": " << count << '\n';
  for (const std::string& f : r.first_failures) out << "  e.g. " << f << '\n';
  return r.failureCount() == 0 ? kExitOk : kExitInternal;
}

}  // namespace nineball::app
