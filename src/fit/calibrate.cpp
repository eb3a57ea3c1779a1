#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "common/parallel_map.hpp"
#include "fit/calibration_stats.hpp"
#include "fit/nelder_mead.hpp"
#include "fit/physics_scorer.hpp"
#include "fit/shot_search.hpp"
#include "nineball/fit.hpp"
#include "nineball/random.hpp"

namespace nineball {
namespace {

// The first step of each parameter's search, as a share of its starting value (or this much
// of a unit for a parameter that starts at 0).
constexpr double kFirstStep = 0.1;
constexpr double kStepAtZero = 0.01;
// The search runs in rounds, each restarting the simplex from the best so far with its steps
// halved (a simplex that closed in early on a rough median opens again). First rounds that
// locate the physics: a refit finds a shot's best only from near it (a contact that comes or
// goes under other physics moves the best elsewhere), so each of these rounds refits the shots
// from their fits under the last round's best, and their medians are only comparable within a
// round. Then rounds that score: the shots' anchors fixed at the located physics, every
// candidate's median is a pure function of its values, and these give the result and its
// uncertainty.
constexpr int kLocatingRounds = 2;
constexpr int kScoringRounds = 2;
constexpr double kLocatingShare = 0.5;  // of the candidates
// A round's simplex has closed in when every vertex lies within this share of the round's steps
// of its best: in the last round, 0.06 % of a parameter's value.
constexpr double kTolerance = 0.05;
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

void say(const CalibrateOptions& o, const std::string& line) {
  if (o.progress) o.progress(line);
}

bool cancelled(const CalibrateOptions& o) {
  return o.cancel && o.cancel->load();
}

std::vector<double> firstSteps(const std::vector<double>& start) {
  std::vector<double> step;
  for (double v : start) step.push_back(v != 0.0 ? kFirstStep * std::abs(v) : kStepAtZero);
  return step;
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

fit::PhysicsScorer::Settings scorerSettings(const PhysicsParams& base, const CalibrateOptions& o) {
  fit::PhysicsScorer::Settings s;
  s.base = base;
  s.set = o.set;
  s.refit_evals = o.refit_evals;
  s.threads = threadsFor(o.threads);
  s.cancel = o.cancel;
  return s;
}

// The training shots, the fits a refit of each starts from, and the seed of each one's searches
// (the shot's own, whatever else is trained).
struct Training {
  std::vector<const fit::RecordedShot*> shots;
  std::vector<fit::Found> anchors;
  std::vector<std::uint64_t> seeds;
};

Training trainingOf(const std::vector<fit::RecordedShot>& read,
                    const std::vector<fit::Found>& first, const std::vector<std::size_t>& train,
                    std::uint64_t seed) {
  Training t;
  for (std::size_t i : train) {
    t.shots.push_back(&read[i]);
    t.anchors.push_back(first[i]);
    t.seeds.push_back(seed + i);
  }
  return t;
}

// Where the locating rounds left the search: the best physics, the steps of the next round, the
// training shots fitted under the best, and how many physics they scored.
struct Located {
  std::vector<double> best;
  std::vector<double> step;
  Training training;
  int scored = 0;
};

// The shots' fits under `values`: each refitted from `refits` (its refit there in the last round)
// and, where `afresh`, also searched afresh, the better kept.
std::vector<fit::Found> anchoredAt(const Training& t, const std::vector<fit::Found>& refits,
                                   const std::vector<double>& values, const PhysicsParams& base,
                                   bool afresh, const CalibrateOptions& o) {
  std::string why;
  const PhysicsParams p = *o.set(base, values, why);
  std::vector<fit::Found> out =
      fit::refitAll(t.shots, p, refits, o.evals / 2, threadsFor(o.threads), o.cancel);
  if (!afresh) return out;
  parallelFor(out.size(), threadsFor(o.threads), [&](std::size_t k) {
    const fit::Found fresh =
        fit::searchShot(*t.shots[k], p, o.evals, FitObjective::Full, t.seeds[k], o.cancel);
    if (fresh.error < out[k].error) out[k] = fresh;
  });
  return out;
}

Located locate(Training training, const PhysicsParams& base, const CalibrateOptions& o) {
  Located l{o.start, firstSteps(o.start), std::move(training), 0};
  const int budget = std::max(1, static_cast<int>(kLocatingShare * o.candidates) / kLocatingRounds);
  for (int round = 0; round < kLocatingRounds && !cancelled(o); ++round) {
    say(o, "locating, round " + std::to_string(round + 1) + " of " +
               std::to_string(kLocatingRounds) + ": from (" + fit::valuesText(l.best) +
               "), steps (" + fit::valuesText(l.step) +
               "), the shots refitted from their fits there");
    fit::PhysicsScorer scorer(l.training.shots, l.training.anchors, scorerSettings(base, o));
    auto objective = [&](const std::vector<double>& x) {
      const bool again = scorer.scored(x);
      const ScoredPhysics& s = scorer.score(x);
      l.scored += again ? 0 : 1;
      say(o, "locating (" + fit::valuesText(x) + "): median " + std::to_string(s.median) + " m");
      return s.median;
    };
    l.best = fit::nelderMead(objective, l.best, l.step, budget, kTolerance, o.cancel).x;
    for (double& s : l.step) s *= 0.5;
    const bool last = round + 1 == kLocatingRounds;
    say(o, "anchoring the training shots at (" + fit::valuesText(l.best) + ")" +
               (last ? ": each refitted and fitted afresh" : ""));
    l.training.anchors = anchoredAt(l.training, scorer.refitsOf(l.best), l.best, base, last, o);
  }
  return l;
}

// What the last scoring round did: where it began and ended, and whether its simplex closed in.
struct LastRound {
  double from = 0.0;
  double to = 0.0;
  bool closed = false;         // within kTolerance of its steps
  std::vector<double> extent;  // of its simplex, about the best
};

struct PhysicsSearch {
  std::vector<double> best;
  LastRound last;
};

std::string candidateLine(const fit::PhysicsScorer& scorer, const ScoredPhysics& s, bool again) {
  return "candidate " + std::to_string(scorer.numberOf(s.values)) + (again ? " again" : "") + " (" +
         fit::valuesText(s.values) + "): median " + std::to_string(s.median) + " m";
}

// The scoring rounds, from where locating left the search, `budget` physics scored in all (one
// tried again is not scored again).
PhysicsSearch searchScored(fit::PhysicsScorer& scorer, const Located& l, int budget,
                           const CalibrateOptions& o) {
  int scored = 0;
  auto objective = [&](const std::vector<double>& x) {
    const bool again = scorer.scored(x);
    const ScoredPhysics& s = scorer.score(x);
    scored += again ? 0 : 1;
    say(o, candidateLine(scorer, s, again));
    return s.median;
  };
  PhysicsSearch search{l.best, {}};
  std::vector<double> step = l.step;
  for (int round = 0; round < kScoringRounds && !cancelled(o); ++round) {
    say(o, "scoring, round " + std::to_string(round + 1) + " of " + std::to_string(kScoringRounds) +
               ": from (" + fit::valuesText(search.best) + "), steps (" + fit::valuesText(step) +
               "), the shots refitted from their fits at (" + fit::valuesText(l.best) + ")");
    // A round after the first begins at the last one's best, scored before: not a candidate.
    const int share = std::max(budget - scored, 1) / (kScoringRounds - round);
    const fit::Minimum m = fit::nelderMead(objective, search.best, step,
                                           share + (round > 0 ? 1 : 0), kTolerance, o.cancel);
    search.last = {scorer.score(search.best).median, m.f, m.converged, m.extent};
    search.best = m.x;
    for (double& s : step) s *= 0.5;
  }
  return search;
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
std::optional<std::size_t> unpinned(const LastRound& last, const CalibrationUncertainty& u) {
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
std::string convergenceOf(const LastRound& last, const Calibration& c, bool& converged) {
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
void judgeConvergence(const LastRound& last, const CalibrateOptions& o, Calibration& c) {
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
    std::snprintf(text, sizeof text, "%.6g (standard error undetermined)", value);
    return text;
  }
  const int places = std::max(0, 1 - static_cast<int>(std::floor(std::log10(*error))));
  std::snprintf(text, sizeof text, "%.*f +- %.*f", places, value, places, *error);
  return text;
}

std::string uncertaintyLine(const Calibration& c, const CalibrateOptions& o) {
  const CalibrationUncertainty& u = c.uncertainty;
  std::string line = "calibrated:";
  for (std::size_t k = 0; k < o.params.size(); ++k) {
    line += (k ? ", " : " ") + o.params[k] + " " + withError(c.values[k], u.stderrs[k]);
  }
  line += " (standard errors: " + u.method + ", " + std::to_string(u.resamples) + " resamples)";
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

  const Located located = locate(trainingOf(read, first, c.train, o.seed), base, o);
  fit::PhysicsScorer scorer(located.training.shots, located.training.anchors,
                            scorerSettings(base, o));
  const PhysicsSearch search =
      searchScored(scorer, located, std::max(o.candidates - located.scored, 1), o);
  c.values = search.best;
  std::string why;
  c.physics = *o.set(base, c.values, why);

  say(o, "fitting every shot under the calibrated physics, the held-out ones afresh too");
  std::vector<fit::Found> from = first;
  std::vector<bool> afresh(shots.size(), true);
  const std::vector<fit::Found>& refits = scorer.refitsOf(c.values);
  for (std::size_t k = 0; k < c.train.size(); ++k) {
    from[c.train[k]] = refits[k];
    afresh[c.train[k]] = false;
  }
  c.fits = finalFits(read, c.physics, from, afresh, o);
  c.train_median = medianOf(c.fits, c.train);
  c.holdout_median = medianOf(c.fits, c.holdout);

  c.tried = scorer.tried();
  c.uncertainty = fit::bootstrapOverShots(
      {c.tried, c.values, firstSteps(o.start), o.params, o.resamples, o.seed});
  judgeConvergence(search.last, o, c);
  say(o, std::string(c.converged ? "converged: " : "not converged: ") + c.convergence);
  say(o, uncertaintyLine(c, o));
  return c;
}

}  // namespace nineball
