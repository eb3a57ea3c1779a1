#include "fit/fit_warnings.hpp"

#include <algorithm>
#include <cmath>

#include "common/limits.hpp"
#include "fit/shot_search.hpp"

namespace nineball::fit {
namespace {

// Two balls' centres are never nearer than a diameter: samples of two balls this near at one
// instant, kOnePlaceRun instants running, are one ball tracked twice (m).
constexpr double kOnePlace = 0.005;
constexpr int kOnePlaceRun = 3;
// A fit has converged when a search from it, given this share of the fit's budget (at least
// two simplexes' worth), lowers its error by no more than kStillFalling, or by less than
// kNegligible (a fit of a noiseless recording halving a micrometre has not failed).
constexpr double kCheckShare = 0.03;
constexpr double kStillFalling = 0.02;
constexpr double kNegligible = 1e-4;

Vec2 sampleOf(const RecordedPath& b, std::size_t i) {
  return {b.x[i], b.y[i]};
}

// Two samples running more than kMoved from where the ball stood, or the last one (a ball
// sampled only where it started and where it stopped): a lone noisy sample moves nothing.
bool movesInRecording(const RecordedPath& b, Vec2 stood) {
  auto far = [&](std::size_t i) { return length(sampleOf(b, i) - stood) > kMoved; };
  const std::size_t n = b.t.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (far(i) && (i + 1 == n || far(i + 1))) return true;
  }
  return false;
}

bool movesInSimulation(const BallTrace& traced, Vec2 stood) {
  for (std::size_t i = 0; i < traced.size(); ++i) {
    if (length(Vec2{traced.x[i], traced.y[i]} - stood) > kMoved) return true;
  }
  return false;
}

bool nothingMoves(const RecordedShot& s) {
  for (std::size_t i = 0; i < s.order.size(); ++i) {
    if (movesInRecording(s.path(i), s.rest[i])) return false;
  }
  return true;
}

// The two balls' samples at the instants both were sampled, kOnePlace apart or less at
// kOnePlaceRun of those instants running.
bool trackedAtOnePlace(const RecordedPath& a, const RecordedPath& b) {
  std::size_t i = 0;
  std::size_t j = 0;
  int run = 0;
  while (i < a.t.size() && j < b.t.size()) {
    if (a.t[i] < b.t[j]) {
      ++i;
    } else if (b.t[j] < a.t[i]) {
      ++j;
    } else {
      run = length(sampleOf(a, i) - sampleOf(b, j)) <= kOnePlace ? run + 1 : 0;
      if (run >= kOnePlaceRun) return true;
      ++i;
      ++j;
    }
  }
  return false;
}

std::vector<std::string> ballsAtOnePlace(const Recording& r) {
  std::vector<std::string> warnings;
  for (std::size_t a = 0; a < r.balls.size(); ++a) {
    for (std::size_t b = a + 1; b < r.balls.size(); ++b) {
      if (trackedAtOnePlace(r.balls[a], r.balls[b])) {
        warnings.push_back("balls " + r.balls[a].name + " and " + r.balls[b].name +
                           " tracked at one place");
      }
    }
  }
  return warnings;
}

// The search's variables that give the fit: the shot, the strike and every ball's place.
Variables variablesOf(const ShotFit& fit) {
  Variables x(kVariables);
  const Shot& shot = *fit.scene.shot;
  x[kHeading] = shot.heading_rad;
  x[kSpeed] = shot.speed;
  x[kSide] = shot.tip.x;
  x[kHeight] = shot.tip.y;
  x[kElevation] = shot.elevation_rad;
  x[kStrike] = fit.strike_time;
  for (const BallState& b : fit.scene.balls) {
    x.push_back(b.pos.x);
    x.push_back(b.pos.y);
  }
  return x;
}

// A short search from the fit still lowering its error by more than kStillFalling: the
// search that found it stopped on a slope, not in a minimum.
bool stillFalling(const RecordedShot& s, const PhysicsParams& p, const ShotFit& fit,
                  const Review& how) {
  const Variables x = variablesOf(fit);
  const int simplex = static_cast<int>(x.size()) + 1;
  const int evals = std::max(static_cast<int>(std::lround(kCheckShare * how.evals)), 2 * simplex);
  const Found again = refineShot(s, p, x, evals, how.objective, how.cancel);
  const double before = how.objective == FitObjective::Early ? fit.rmse.early : fit.rmse.full;
  const double gain = before - again.error;
  return gain > kStillFalling * before && gain > kNegligible;
}

}  // namespace

std::vector<std::string> fitWarnings(const RecordedShot& s, const PhysicsParams& p,
                                     const ShotFit& fit, const Review& how) {
  std::vector<std::string> warnings;
  if (nothingMoves(s)) warnings.push_back("nothing moves");
  for (std::string& w : ballsAtOnePlace(*s.recording)) warnings.push_back(std::move(w));
  if (s.cue_moving_at_start) warnings.push_back("recording starts after the strike");
  if (stillFalling(s, p, fit, how)) warnings.push_back("did not converge");
  return warnings;
}

std::vector<std::string> unreproducedBalls(const RecordedShot& s, const ShotFit& fit) {
  Scene traced = fit.scene;
  traced.until = std::max(s.end - fit.strike_time, kMinRun);
  traced.trace = TraceRequest{limits::kMinTraceHz, false};
  const SimResult run = simulate(traced);
  std::vector<std::string> unreproduced;
  for (std::size_t i = 0; i < s.order.size(); ++i) {
    const bool recorded = movesInRecording(s.path(i), s.rest[i]);
    const bool simulated = run.trace && movesInSimulation(run.trace->balls[i], traced.balls[i].pos);
    if (recorded != simulated) unreproduced.push_back(fit.names[i]);
  }
  return unreproduced;
}

void review(const RecordedShot& s, const PhysicsParams& p, ShotFit& fit, const Review& how) {
  fit.warnings = fitWarnings(s, p, fit, how);
  fit.unreproduced = unreproducedBalls(s, fit);
}

}  // namespace nineball::fit
