#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "fit/recorded_shot.hpp"
#include "nineball/fit.hpp"

// What a fitted shot's line says besides the fit: why it may mislead (its warnings) and the
// balls it does not reproduce (docs/calibrating.md).
namespace nineball::fit {

/// How the fit under review was searched: its budget, what it minimised, and the flag that
/// stops the review's own search.
struct Review {
  int evals = 0;
  FitObjective objective = FitObjective::Full;
  const std::atomic<bool>* cancel = nullptr;
};

/// The warnings, in this order: "nothing moves", "balls X and Y tracked at one place" (each
/// such pair, in the recording's order), "recording starts after the strike", "did not
/// converge".
std::vector<std::string> fitWarnings(const RecordedShot& s, const PhysicsParams& p,
                                     const ShotFit& fit, const Review& how);

/// The recorded balls, in the scene's order, that move beyond noise in the recording and not
/// in the fitted scene simulated over the recording's span, or the other way round.
std::vector<std::string> unreproducedBalls(const RecordedShot& s, const ShotFit& fit);

/// Sets fit.warnings and fit.unreproduced.
void review(const RecordedShot& s, const PhysicsParams& p, ShotFit& fit, const Review& how);

}  // namespace nineball::fit
