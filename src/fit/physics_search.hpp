#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fit/recorded_shot.hpp"
#include "fit/shot_search.hpp"
#include "nineball/fit.hpp"

namespace nineball::fit {

/// The training shots, the fits a refit of each starts from, and the seed of each one's searches
/// (the shot's own, whatever else is trained).
struct Training {
  std::vector<const RecordedShot*> shots;
  std::vector<Found> anchors;
  std::vector<std::uint64_t> seeds;
};

/// What the last round of the search did: where it began and ended, and how far its simplex
/// closed in.
struct LastRound {
  double from = 0.0;           ///< m, the median of its first physics
  double to = 0.0;             ///< m, of its best
  bool closed = false;         ///< within its tolerance
  std::vector<double> extent;  ///< of its last simplex about the best, in each parameter
};

/// Where the search over the physics ended.
struct PhysicsSearch {
  std::vector<double> best;
  LastRound last;
  std::vector<ScoredPhysics> tried;  ///< every physics the scoring rounds scored
  std::vector<Found> refits;         ///< the training shots' refits under the best
};

/// The first step of each parameter's search: a share of its starting value, or a share of a
/// unit for a parameter that starts at 0.
std::vector<double> firstSteps(const std::vector<double>& start);

/// The simplex over the parameters (docs/calibrating.md, "How the search works"): rounds that
/// locate the physics, the shots refitted from their fits under the last round's best; then
/// rounds that score every candidate as a pure function of its values, the shots' anchors fixed
/// at the located physics. `training.anchors`: the shots' fits under `base`.
PhysicsSearch searchPhysics(Training training, const PhysicsParams& base,
                            const CalibrateOptions& o);

/// A line of progress, if the options take them.
void say(const CalibrateOptions& o, const std::string& line);

bool cancelled(const CalibrateOptions& o);

}  // namespace nineball::fit
