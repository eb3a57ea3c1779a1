#pragma once

#include <deque>
#include <map>
#include <vector>

#include "fit/recorded_shot.hpp"
#include "fit/shot_search.hpp"
#include "nineball/fit.hpp"

namespace nineball::fit {

/// Scores candidate physics for a calibration: the median error of the training shots, each
/// refitted under the physics (a short search over the whole shot) from a fixed anchor, its fit
/// under one physics chosen before any candidate is scored. So the score is a pure function of
/// the candidate's values, the anchors and the settings: the same physics scores the same
/// whenever the search tries it, after whatever else (and is simulated only the first time).
class PhysicsScorer {
 public:
  struct Settings {
    PhysicsParams base;  ///< the recordings' physics, the parameters set into it
    PhysicsSetter set;
    int refit_evals = 0;  ///< simulations of a training shot's refit under a candidate
    int threads = 1;
    const std::atomic<bool>* cancel = nullptr;
  };

  /// `shots`: the training shots; `anchors`: each one's fit the refits start from.
  PhysicsScorer(std::vector<const RecordedShot*> shots, std::vector<Found> anchors,
                Settings settings);

  /// Whether `values` has been scored (then score() simulates nothing).
  bool scored(const std::vector<double>& values) const;
  /// Of the physics scored, the place of `values` in the order first tried, from 1.
  std::size_t numberOf(const std::vector<double>& values) const;
  /// The physics `values` scored; the reference holds until the scorer goes.
  const ScoredPhysics& score(const std::vector<double>& values);
  /// The training shots' refits under a physics scored, in the shots' order.
  const std::vector<Found>& refitsOf(const std::vector<double>& values);
  /// Every physics scored, in the order first tried.
  std::vector<ScoredPhysics> tried() const;

 private:
  struct Entry {
    ScoredPhysics scored;
    std::vector<Found> refits;
  };

  const Entry& entryOf(const std::vector<double>& values);

  std::vector<const RecordedShot*> shots_;
  std::vector<Found> anchors_;
  Settings settings_;
  std::deque<Entry> entries_;
  std::map<std::vector<double>, std::size_t> index_;
};

/// The training shots refitted under `p` from `from` (in the same order), each with `evals`
/// simulations, on up to `threads` threads.
std::vector<Found> refitAll(const std::vector<const RecordedShot*>& shots, const PhysicsParams& p,
                            const std::vector<Found>& from, int evals, int threads,
                            const std::atomic<bool>* cancel);

/// The median of a list (0 for none).
double median(std::vector<double> v);

/// Values as the progress lines print them: each the shortest text that reads back as exactly
/// it, so that a physics tried twice reads the same and two physics never do.
std::string valuesText(const std::vector<double>& values);

}  // namespace nineball::fit
