#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "nineball/fit.hpp"

namespace nineball::fit {

/// What the uncertainty of a calibration is worked out from.
struct BootstrapInput {
  std::vector<ScoredPhysics> tried;  ///< every physics the search scored
  std::vector<double> best;          ///< the calibrated values (one of `tried`)
  std::vector<double> scale;         ///< a typical step of each parameter (its first step)
  std::vector<std::string> names;    ///< the parameters', for the reasons
  int resamples = 200;
  std::uint64_t seed = 1;
};

/// Standard errors and correlations of the calibrated values by a bootstrap over the training
/// shots, without a further simulation. The calibrated values are those of the physics tried
/// whose median error over the training shots is the least; each resample (as many training
/// shots drawn with replacement, by the seed) gives every physics tried the median of its
/// resampled errors, and so a best physics of its own. The standard deviations and correlations
/// of those over the resamples are the answer. A parameter's is undetermined (empty, and
/// `why_not` says so) where the resamples' best physics tie in it (a median that does not feel
/// it), lie at the edge of the values tried in more than a tenth of the resamples, or are the
/// same in every resample (an uncertainty below the spacing of the physics tried).
CalibrationUncertainty bootstrapOverShots(const BootstrapInput& in);

}  // namespace nineball::fit
