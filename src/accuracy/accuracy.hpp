#pragma once

#include <string>
#include <utility>
#include <vector>

#include "nineball/params.hpp"

namespace nineball {

/// The worst error of one canonical case against its closed form.
struct CaseError {
  std::string name;  ///< head-on, cut-direction, cushion, stopping, cradle, ...
  std::string unit;  ///< "%" (relative to the formula), "deg" or "mm"
  double worst = 0.0;
  double target = 0.0;  ///< the accuracy target of the case, same unit

  /// worst / target: at most 1 when the case meets its target.
  double score() const { return worst / target; }
};

/// Which of the points (run time, error), both to be small, no other point beats on both:
/// the Pareto front.
std::vector<bool> paretoFront(const std::vector<std::pair<double, double>>& time_error);

/// The largest score over the cases: at most 1 when every case meets its target.
double worstScore(const std::vector<CaseError>& errors);

/// Runs every canonical case under the given solver settings (physics: the real preset with
/// the friction and restitution each case needs) and returns its worst error.
std::vector<CaseError> runAccuracyCases(const StepParams& step);

/// Simulated seconds and steps of the standard break (seed 1, 10 m/s) to rest, and the wall
/// time of that run in milliseconds.
struct BreakTiming {
  double sim_time = 0.0;
  long steps = 0;
  double wall_ms = 0.0;
};
BreakTiming timeBreak(const StepParams& step, const PhysicsParams& physics = PhysicsParams::real());

/// The cue ball's velocity along the break line 0.3 s after a 10 m/s break into a rack whose
/// neighbouring balls are `gap` metres apart, as a fraction of the break speed (negative: it
/// comes back off the rack).
double breakCueRebound(const StepParams& step, double gap);

}  // namespace nineball
