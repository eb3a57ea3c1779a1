#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "common/parallel_map.hpp"
#include "fit/calibration_stats.hpp"
#include "fit/physics_scorer.hpp"
#include "fit/physics_search.hpp"
#include "fit/shot_search.hpp"
#include "nineball/fit.hpp"
#include "nineball/random.hpp"

namespace nineball {
namespace {

using fit::cancelled;
using fit::say;

// A last round that lowered the median by this share or more has not converged: a further one
// might lower it again.
constexpr double kStillFalling = 0.01;

// Shots held out drawn by the seed (Fisher and Yates over splitmix64), at least one trained.
void split(std::size_t n, double holdout, std::uint64_t seed, std::vector<std::size_t>& train,
           std::vector<std::size_t>& held) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::uint64_t state = seed;
  for (std::size_t i = n; i > 1; --i) {
    std::swap(order[i - 1], order[splitmix64(state) % i]);
  }
  std::size_t kept = static_cast<std::size_t>(std::lround(holdout * static_cast<double>(n)));
  kept = std::min(kept, n - 1);
  held.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(kept));
  train.assign(order.begin() + static_cast<std::ptrdiff_t>(kept), order.end());
  std::sort(held.begin(), held.end());
  std::sort(train.begin(), train.end());
}

std::vector<fit::RecordedShot> readAll(const std::vector<Recording>& shots) {
  std::vector<fit::RecordedShot> read;
  for (const Recording& r : shots) {
    read.push_back(fit::readRecording(r));
    fit::separate(read.back().rest, r.table, r.physics.ball_radius);
  }
  return read;
}

std::vector<fit::Found> searchAll(const std::vector<fit::RecordedShot>& read,
                                  const PhysicsParams& p, const CalibrateOptions& o) {
  std::vector<fit::Found> found(read.size());
  parallelFor(read.size(), threadsFor(o.threads), [&](std::size_t i) {
    found[i] = fit::searchShot(read[i], p, o.evals, FitObjective::Full, o.seed + i, o.cancel);
  });
  return found;
}

fit::Training trainingOf(const std::vector<fit::RecordedShot>& read,
                         const std::vector<fit::Found>& first,
                         const std::vector<std::size_t>& train, std::uint64_t seed) {
  fit::Training t;
  for (std::size_t i : train) {
    t.shots.push_back(&read[i]);
    t.anchors.push_back(first[i]);
    t.seeds.push_back(seed + i);
  }
  return t;
}

// Each shot fitted under the calibrated physics from where the search left it: a training
// shot from its refit under the best physics (from its fit searched afresh at the located
// physics, a step or two away), a held-out shot from its first fit, and that one afresh too, the
// better kept (a shot refitted only from where other physics left it may sit in a false minimum
// the new physics has moved).
std::vector<ShotFit> finalFits(const std::vector<fit::RecordedShot>& read,
                               const PhysicsParams& physics, const std::vector<fit::Found>& from,
                               const std::vector<bool>& afresh, const CalibrateOptions& o) {
  std::vector<ShotFit> fits(read.size());
  parallelFor(read.size(), threadsFor(o.threads), [&](std::size_t i) {
    fit::Found best =
        fit::refineShot(read[i], physics, from[i].x, o.evals / 2, FitObjective::Full, o.cancel);
    if (afresh[i]) {
      const fit::Found fresh =
          fit::searchShot(read[i], physics, o.evals, FitObjective::Full, o.seed + i, o.cancel);
      if (fresh.error < best.error) best = fresh;
    }
    fits[i] = fit::shotFitOf(read[i], physics, best);
  });
  return fits;
}

double medianOf(const std::vector<ShotFit>& fits, const std::vector<std::size_t>& which) {
  std::vector<double> errors;
  for (std::size_t i : which) errors.push_back(fits[i].rmse.full);
  return fit::median(errors);
}

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100.0 * share);
  return text;
}

// The last round's simplex is pinned down in a parameter when it spans under kPinned of the
// parameter's standard error: the search has found the best more finely than the shots
// determine it.
constexpr double kPinned = 0.5;

// The first parameter with a standard error that the last round's simplex spans more of, if any.
std::optional<std::size_t> unpinned(const fit::LastRound& last, const CalibrationUncertainty& u) {
  for (std::size_t k = 0; k < last.extent.size(); ++k) {
    if (u.stderrs[k] && last.extent[k] > kPinned * *u.stderrs[k]) return k;
  }
  return std::nullopt;
}

bool everyStderr(const CalibrationUncertainty& u) {
  return std::all_of(u.stderrs.begin(), u.stderrs.end(),
                     [](const std::optional<double>& e) { return e.has_value(); });
}

// Why the search has converged or not, and whether (in `converged`), judged by its last round
// alone: the standard errors' own verdict is added by judgeConvergence.
std::string convergenceOf(const fit::LastRound& last, const Calibration& c, bool& converged) {
  const double fell = last.from > 0.0 && std::isfinite(last.from) && std::isfinite(last.to)
                          ? (last.from - last.to) / last.from
                          : 0.0;
  const std::string in_it = " (the median fell by " + percent(fell) + " in it)";
  converged = false;
  if (fell >= kStillFalling) {
    return std::string(last.closed ? "the last round's simplex closed in, but"
                                   : "candidate budget spent while") +
           " the median still fell by " + percent(fell) + " in the last round";
  }
  if (last.closed) {
    converged = true;
    return "simplex within tolerance in the last round" + in_it;
  }
  if (const std::optional<std::size_t> loose = unpinned(last, c.uncertainty)) {
    return "candidate budget spent while the last round's simplex still spanned more than half "
           "a standard error of " +
           c.params[*loose] + in_it;
  }
  if (!everyStderr(c.uncertainty)) {
    return "candidate budget spent before the last round's simplex closed in" + in_it;
  }
  converged = true;
  return "the last round's simplex spans under half a standard error of every parameter" + in_it;
}

// Converged: the last round no longer lowered the median by kStillFalling, its simplex closed in
// (within its tolerance, or to under kPinned of every standard error), and every standard error
// is determined.
void judgeConvergence(const fit::LastRound& last, const CalibrateOptions& o, Calibration& c) {
  if (cancelled(o)) {
    c.converged = false;
    c.convergence = "cancelled";
    return;
  }
  c.convergence = convergenceOf(last, c, c.converged);
  if (!c.uncertainty.why_not.empty()) {
    c.converged = false;
    c.convergence += "; a standard error is undetermined: " + c.uncertainty.why_not;
  }
}

// A value and its standard error as a paper prints them: the error to two significant digits,
// the value to the same place.
std::string withError(double value, const std::optional<double>& error) {
  char text[96];
  if (!error) {
    std::snprintf(text, sizeof text, "%.6g +- undetermined", value);
    return text;
  }
  const int places = std::max(0, 1 - static_cast<int>(std::floor(std::log10(*error))));
  std::snprintf(text, sizeof text, "%.*f +- %.*f", places, value, places, *error);
  return text;
}

std::string uncertaintyLine(const Calibration& c, const CalibrateOptions& o) {
  const CalibrationUncertainty& u = c.uncertainty;
  std::string line = "calibrated (standard errors: " + u.method + ", " +
                     std::to_string(u.resamples) + " resamples):";
  for (std::size_t k = 0; k < o.params.size(); ++k) {
    line += (k ? ", " : " ") + o.params[k] + " " + withError(c.values[k], u.stderrs[k]);
  }
  for (std::size_t j = 0; j < o.params.size(); ++j) {
    for (std::size_t k = j + 1; k < o.params.size(); ++k) {
      if (!u.correlation[j][k]) continue;
      char r[16];
      std::snprintf(r, sizeof r, "%.2f", *u.correlation[j][k]);
      line += "; correlation " + o.params[j] + "/" + o.params[k] + " " + r;
    }
  }
  return line;
}

}  // namespace

Calibration calibrate(const std::vector<Recording>& shots, const CalibrateOptions& o) {
  if (shots.empty()) throw std::invalid_argument("no shots to calibrate");
  if (o.params.size() != o.start.size() || !o.set) {
    throw std::invalid_argument("calibrate: each parameter needs its start and a setter");
  }
  Calibration c;
  c.params = o.params;
  split(shots.size(), o.holdout, o.seed, c.train, c.holdout);
  const PhysicsParams base = shots.front().physics;
  const std::vector<fit::RecordedShot> read = readAll(shots);
  say(o, "fitting " + std::to_string(shots.size()) + " shots under the recordings' physics");
  const std::vector<fit::Found> first = searchAll(read, base, o);

  const fit::PhysicsSearch search =
      fit::searchPhysics(trainingOf(read, first, c.train, o.seed), base, o);
  c.values = search.best;
  std::string why;
  c.physics = *o.set(base, c.values, why);

  say(o, "fitting every shot under the calibrated physics, the held-out ones afresh too");
  std::vector<fit::Found> from = first;
  std::vector<bool> afresh(shots.size(), true);
  for (std::size_t k = 0; k < c.train.size(); ++k) {
    from[c.train[k]] = search.refits[k];
    afresh[c.train[k]] = false;
  }
  c.fits = finalFits(read, c.physics, from, afresh, o);
  c.train_median = medianOf(c.fits, c.train);
  c.holdout_median = medianOf(c.fits, c.holdout);

  c.tried = search.tried;
  c.uncertainty = fit::bootstrapOverShots(
      {c.tried, c.values, fit::firstSteps(o.start), o.params, o.resamples, o.seed});
  judgeConvergence(search.last, o, c);
  say(o, std::string(c.converged ? "converged: " : "not converged: ") + c.convergence);
  say(o, uncertaintyLine(c, o));
  return c;
}

}  // namespace nineball
