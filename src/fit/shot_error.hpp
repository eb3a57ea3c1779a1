#pragma once

#include <limits>
#include <vector>

#include "fit/recorded_shot.hpp"
#include "nineball/fit.hpp"
#include "nineball/sim.hpp"

namespace nineball::fit {

/// The searched variables of a shot, in this order; then, when the balls' places are searched
/// too, x and y of each scene ball in turn (their samples before the strike hold them).
enum Variable { kHeading, kSpeed, kSide, kHeight, kElevation, kStrike, kVariables };

using Variables = std::vector<double>;

/// The shot's variables and every ball's place at the strike.
Variables withPlaces(const RecordedShot& s, Variables x);

/// Ball i's place at the strike as the recording's samples put it.
Vec2 recordedPlace(const RecordedShot& s, const Variables& x, std::size_t i);

/// Ball i's place at the strike: searched, or as the recording's samples put it.
Vec2 placeOf(const RecordedShot& s, const Variables& x, std::size_t i);

/// Which samples an error counts, and how.
struct Window {
  /// Samples recorded after this time are left out.
  double until = std::numeric_limits<double>::infinity();
  bool cue_only = false;
  FitObjective weighting = FitObjective::Full;
};

/// The window of a whole shot under `objective`.
Window wholeShot(FitObjective objective);

/// The variables made legal: a speed the scene takes, a tip inside the miscue limit, an
/// elevation from 0 to 60 degrees, a strike before the cue ball moves, balls within a
/// centimetre of where the samples put them, apart and on the table.
Variables legal(const RecordedShot& s, const PhysicsParams& p, Variables x);

/// The scene the variables describe, simulated up to the window's end (the reference engine,
/// traced so that every sample can be read off exactly).
Scene sceneOf(const RecordedShot& s, const PhysicsParams& p, const Variables& x, const Window& w);

/// The weighted RMSE (m) of a simulated scene against the recording's samples in the window.
double windowError(const RecordedShot& s, const Scene& scene, const SimResult& run, double strike,
                   const Window& w);

/// Simulates the variables (made legal, a penalty for how far they were outside) and scores
/// them: the search's objective.
double searchError(const RecordedShot& s, const PhysicsParams& p, const Variables& x,
                   const Window& w);

}  // namespace nineball::fit
