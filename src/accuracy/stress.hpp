#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "nineball/params.hpp"
#include "nineball/sim.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// What the numerical stability stress runs.
struct StressOptions {
  std::uint64_t seed = 1;
  int random_layouts = 200;     ///< random tables and shots, up to 13 m/s and full spin
  int random_settings = 300;    ///< scenes with every setting drawn from its allowed range
  int crowded_balls = 100;      ///< balls on the crowded table
  double long_run_s = 60.0;     ///< simulated seconds of the frictionless endless run
  double rest_within_s = 60.0;  ///< every scenario with a cloth must be at rest by then
  StepParams step;              ///< solver settings of every scenario
  /// Only the scenarios whose names start with one of these ("settings #616 "); all if empty.
  std::vector<std::string> only;
  /// Also runs every scenario (twice) through the reference engine, checking its result.
  bool reference = true;
};

/// What it found.
struct StressReport {
  std::map<std::string, int> scenarios;  ///< kind -> count
  long steps = 0;
  long checks = 0;
  std::map<std::string, long> failures;     ///< check -> count
  std::vector<std::string> first_failures;  ///< the first few, described
  double simulated_s = 0.0;
  long reference_runs = 0;  ///< scenarios run through the reference engine too

  long failureCount() const;
};

/// The first scenario whose name starts with `name`, as a scene (to run it on its own).
std::optional<Scene> stressScene(const StressOptions& options, const std::string& name);

/// Runs every scenario twice, checking after every step: no NaN or infinity; every ball inside
/// the cushions or pocketed; no two balls overlapping by more than 0.1 mm; kinetic energy
/// (with rotation) never rising outside a cue strike; a ball pocketed only with an event; all
/// balls at rest within rest_within_s; the two runs identical. With `reference`, each scenario
/// is also run twice through the reference engine and its result checked the same way (at its
/// end: it has no steps).
StressReport runStress(const StressOptions& options);

}  // namespace nineball
