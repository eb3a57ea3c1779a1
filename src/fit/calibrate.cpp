#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "common/parallel_map.hpp"
#include "fit/nelder_mead.hpp"
#include "fit/shot_search.hpp"
#include "nineball/fit.hpp"
#include "nineball/random.hpp"

namespace nineball {
namespace {

// The first step of each parameter's search, as a share of its starting value (or this much
// of a unit for a parameter that starts at 0).
constexpr double kFirstStep = 0.1;
constexpr double kStepAtZero = 0.01;
// The searches over the physics: the second starts from shots refitted under the first's
// best physics, so that no shot is held to where the recordings' own physics put it.
constexpr int kRounds = 3;

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

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

class Calibrator {
 public:
  Calibrator(const std::vector<Recording>& shots, const CalibrateOptions& o)
      : o_(o), threads_(threadsFor(o.threads)) {
    for (const Recording& r : shots) {
      read_.push_back(fit::readRecording(r));
      fit::separate(read_.back().rest, r.table, r.physics.ball_radius);
    }
    found_.resize(shots.size());
  }

  // Every shot fitted afresh under `p` as well, the better fit kept: a shot refitted only from
  // where other physics left it may sit in a false minimum the new physics has moved.
  void fitAfresh(const PhysicsParams& p, int evals) {
    parallelFor(found_.size(), threads_, [&](std::size_t i) {
      const fit::Found fresh =
          fit::searchShot(read_[i], p, evals, FitObjective::Full, o_.seed + i, o_.cancel);
      if (fresh.error < found_[i].error) found_[i] = fresh;
    });
  }

  void fitAll(const PhysicsParams& p, const std::vector<std::size_t>& which, int evals,
              bool from_scratch) {
    parallelFor(which.size(), threads_, [&](std::size_t k) {
      const std::size_t i = which[k];
      found_[i] =
          from_scratch
              ? fit::searchShot(read_[i], p, evals, FitObjective::Full, o_.seed + i, o_.cancel)
              : fit::refineShot(read_[i], p, found_[i].x, evals, FitObjective::Full, o_.cancel);
    });
  }

  // The median error of the training shots, each refitted from where it stands under `p`.
  double medianUnder(const PhysicsParams& p, const std::vector<std::size_t>& train) {
    std::vector<double> errors(train.size());
    parallelFor(train.size(), threads_, [&](std::size_t k) {
      const std::size_t i = train[k];
      errors[k] =
          fit::refineShot(read_[i], p, found_[i].x, o_.refit_evals, FitObjective::Full, o_.cancel)
              .error;
    });
    return median(errors);
  }

  ShotFit fitOf(std::size_t i, const PhysicsParams& p) const {
    return fit::shotFitOf(read_[i], p, found_[i]);
  }

  double medianError(const std::vector<std::size_t>& which) const {
    std::vector<double> errors;
    for (std::size_t i : which) errors.push_back(found_[i].error);
    return median(errors);
  }

 private:
  const CalibrateOptions& o_;
  int threads_;
  std::vector<fit::RecordedShot> read_;
  std::vector<fit::Found> found_;
};

void say(const CalibrateOptions& o, const std::string& line) {
  if (o.progress) o.progress(line);
}

std::string valuesText(const std::vector<double>& v) {
  std::ostringstream out;
  out.precision(5);
  for (std::size_t i = 0; i < v.size(); ++i) out << (i ? ", " : "") << v[i];
  return out.str();
}

}  // namespace

Calibration calibrate(const std::vector<Recording>& shots, const CalibrateOptions& o) {
  if (shots.empty()) throw std::invalid_argument("no shots to calibrate");
  if (o.params.size() != o.start.size() || !o.set) {
    throw std::invalid_argument("calibrate: each parameter needs its start and a setter");
  }
  Calibration c;
  split(shots.size(), o.holdout, o.seed, c.train, c.holdout);
  const PhysicsParams base = shots.front().physics;
  Calibrator calibrator(shots, o);
  std::vector<std::size_t> every(shots.size());
  std::iota(every.begin(), every.end(), 0);
  say(o, "fitting " + std::to_string(shots.size()) + " shots under the recordings' physics");
  calibrator.fitAll(base, every, o.evals, true);

  std::vector<double> step;
  for (double v : o.start) step.push_back(v != 0.0 ? kFirstStep * std::abs(v) : kStepAtZero);
  std::vector<double> values = o.start;
  PhysicsParams physics = base;
  int candidate = 0;
  auto objective = [&](const std::vector<double>& x) {
    std::string why;
    const std::optional<PhysicsParams> p = o.set(base, x, why);
    if (!p) return std::numeric_limits<double>::infinity();
    const double m = calibrator.medianUnder(*p, c.train);
    say(o, "candidate " + std::to_string(++candidate) + " (" + valuesText(x) + "): median " +
               std::to_string(m) + " m");
    return m;
  };
  for (int round = 0; round < kRounds; ++round) {
    const int budget = o.candidates / kRounds;
    const fit::Minimum m = fit::nelderMead(objective, values, step, budget, 1e-3, o.cancel);
    values = m.x;
    std::string why;
    physics = *o.set(base, values, why);
    // Every shot fitted again under the best physics so far: the next round starts there.
    calibrator.fitAll(physics, every, o.evals / 2, false);
    for (double& s : step) s *= 0.5;
  }
  say(o, "fitting every shot afresh under the calibrated physics");
  calibrator.fitAfresh(physics, o.evals);
  c.values = values;
  c.physics = physics;
  for (std::size_t i = 0; i < shots.size(); ++i) c.fits.push_back(calibrator.fitOf(i, physics));
  c.train_median = calibrator.medianError(c.train);
  c.holdout_median = calibrator.medianError(c.holdout);
  return c;
}

}  // namespace nineball
