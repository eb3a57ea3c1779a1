#include "fit/physics_search.hpp"

#include <algorithm>
#include <cmath>

#include "common/parallel_map.hpp"
#include "fit/nelder_mead.hpp"
#include "fit/physics_scorer.hpp"

namespace nineball::fit {
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

PhysicsScorer::Settings scorerSettings(const PhysicsParams& base, const CalibrateOptions& o) {
  PhysicsScorer::Settings s;
  s.base = base;
  s.set = o.set;
  s.refit_evals = o.refit_evals;
  s.threads = threadsFor(o.threads);
  s.cancel = o.cancel;
  return s;
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
std::vector<Found> anchoredAt(const Training& t, const std::vector<Found>& refits,
                              const std::vector<double>& values, const PhysicsParams& base,
                              bool afresh, const CalibrateOptions& o) {
  std::string why;
  const PhysicsParams p = *o.set(base, values, why);
  std::vector<Found> out =
      refitAll(t.shots, p, refits, o.evals / 2, threadsFor(o.threads), o.cancel);
  if (!afresh) return out;
  parallelFor(out.size(), threadsFor(o.threads), [&](std::size_t k) {
    const Found fresh =
        searchShot(*t.shots[k], p, o.evals, FitObjective::Full, t.seeds[k], o.cancel);
    if (fresh.error < out[k].error) out[k] = fresh;
  });
  return out;
}

Located locate(Training training, const PhysicsParams& base, const CalibrateOptions& o) {
  Located l{o.start, firstSteps(o.start), std::move(training), 0};
  const int budget = std::max(1, static_cast<int>(kLocatingShare * o.candidates) / kLocatingRounds);
  for (int round = 0; round < kLocatingRounds && !cancelled(o); ++round) {
    say(o, "locating, round " + std::to_string(round + 1) + " of " +
               std::to_string(kLocatingRounds) + ": from (" + valuesText(l.best) + "), steps (" +
               valuesText(l.step) + "), the shots refitted from their fits there");
    PhysicsScorer scorer(l.training.shots, l.training.anchors, scorerSettings(base, o));
    auto objective = [&](const std::vector<double>& x) {
      const bool again = scorer.scored(x);
      const ScoredPhysics& s = scorer.score(x);
      l.scored += again ? 0 : 1;
      say(o, "locating (" + valuesText(x) + "): median " + std::to_string(s.median) + " m");
      return s.median;
    };
    l.best = nelderMead(objective, l.best, l.step, budget, kTolerance, o.cancel).x;
    for (double& s : l.step) s *= 0.5;
    const bool last = round + 1 == kLocatingRounds;
    say(o, "anchoring the training shots at (" + valuesText(l.best) + ")" +
               (last ? ": each refitted and fitted afresh" : ""));
    l.training.anchors = anchoredAt(l.training, scorer.refitsOf(l.best), l.best, base, last, o);
  }
  return l;
}

std::string candidateLine(const PhysicsScorer& scorer, const ScoredPhysics& s, bool again) {
  return "candidate " + std::to_string(scorer.numberOf(s.values)) + (again ? " again" : "") + " (" +
         valuesText(s.values) + "): median " + std::to_string(s.median) + " m";
}

// The scoring rounds, from where locating left the search, `budget` physics scored in all (one
// tried again is not scored again).
PhysicsSearch searchScored(PhysicsScorer& scorer, const Located& l, int budget,
                           const CalibrateOptions& o) {
  int scored = 0;
  auto objective = [&](const std::vector<double>& x) {
    const bool again = scorer.scored(x);
    const ScoredPhysics& s = scorer.score(x);
    scored += again ? 0 : 1;
    say(o, candidateLine(scorer, s, again));
    return s.median;
  };
  PhysicsSearch search{l.best, {}, {}, {}};
  std::vector<double> step = l.step;
  for (int round = 0; round < kScoringRounds && !cancelled(o); ++round) {
    say(o, "scoring, round " + std::to_string(round + 1) + " of " + std::to_string(kScoringRounds) +
               ": from (" + valuesText(search.best) + "), steps (" + valuesText(step) +
               "), the shots refitted from their fits at (" + valuesText(l.best) + ")");
    // A round after the first begins at the last one's best, scored before: not a candidate.
    const int share = std::max(budget - scored, 1) / (kScoringRounds - round);
    const Minimum m =
        nelderMead(objective, search.best, step, share + (round > 0 ? 1 : 0), kTolerance, o.cancel);
    search.last = {scorer.score(search.best).median, m.f, m.converged, m.extent};
    search.best = m.x;
    for (double& s : step) s *= 0.5;
  }
  return search;
}

}  // namespace

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

PhysicsSearch searchPhysics(Training training, const PhysicsParams& base,
                            const CalibrateOptions& o) {
  const Located located = locate(std::move(training), base, o);
  PhysicsScorer scorer(located.training.shots, located.training.anchors, scorerSettings(base, o));
  PhysicsSearch search =
      searchScored(scorer, located, std::max(o.candidates - located.scored, 1), o);
  search.tried = scorer.tried();
  search.refits = scorer.refitsOf(search.best);
  return search;
}

}  // namespace nineball::fit
