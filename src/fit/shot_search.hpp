#pragma once

#include <atomic>
#include <cstdint>

#include "fit/shot_error.hpp"

namespace nineball::fit {

/// The best variables a search found, their error and the simulations it took.
struct Found {
  Variables x;
  double error = 0.0;
  int evals = 0;
};

/// The whole staged search of one shot (see fitShot): the cue ball alone up to its first
/// event, then tips from a grid over the first second after it, then ever longer windows, then
/// restarts about the best until `evals` simulations are spent.
Found searchShot(const RecordedShot& s, const PhysicsParams& p, int evals, FitObjective objective,
                 std::uint64_t seed, const std::atomic<bool>* cancel);

/// A search over the whole shot from `from` with small first steps: a shot fitted once,
/// fitted again under other physics.
Found refineShot(const RecordedShot& s, const PhysicsParams& p, const Variables& from, int evals,
                 FitObjective objective, const std::atomic<bool>* cancel);

/// The shot fit the variables give, with both errors.
ShotFit shotFitOf(const RecordedShot& s, const PhysicsParams& p, const Found& f);

}  // namespace nineball::fit
