#pragma once

#include <string>
#include <vector>

#include "nineball/params.hpp"

namespace nineball {

/// The worst error of one canonical case against its closed form.
struct CaseError {
  std::string name;  ///< head-on, cut-sweep, cushion, stopping, cradle
  std::string unit;  ///< "%" (relative to the formula) or "deg"
  double worst = 0.0;
};

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
