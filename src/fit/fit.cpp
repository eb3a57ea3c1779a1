#include "nineball/fit.hpp"

#include <algorithm>
#include <mutex>
#include <stdexcept>

#include "common/parallel_map.hpp"
#include "fit/fit_warnings.hpp"
#include "fit/shot_search.hpp"
#include "nineball/cancel.hpp"

namespace nineball {

FitErrors fitErrors(const Recording& r, const Scene& scene, const std::vector<std::string>& names,
                    double strike_time) {
  fit::RecordedShot s;
  s.recording = &r;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto found = std::find_if(r.balls.begin(), r.balls.end(),
                                    [&](const RecordedPath& b) { return b.name == names[i]; });
    if (found == r.balls.end()) throw std::invalid_argument("no recorded ball " + names[i]);
    s.order.push_back(static_cast<std::size_t>(found - r.balls.begin()));
    s.rest.push_back(scene.balls.at(i).pos);
    s.end = std::max(s.end, found->t.back());
  }
  Scene traced = scene;
  traced.until = std::max(s.end - strike_time, 1e-3);
  traced.trace = TraceRequest{1.0, false};
  const SimResult run = simulate(traced);
  FitErrors e;
  e.full = fit::windowError(s, traced, run, strike_time, fit::wholeShot(FitObjective::Full));
  e.early = fit::windowError(s, traced, run, strike_time, fit::wholeShot(FitObjective::Early));
  return e;
}

ShotFit fitShot(const Recording& r, const FitOptions& options) {
  // A cancelled fit is thrown away: its simulations may stop at their next event too.
  const CancelScope scope(options.cancel);
  fit::RecordedShot s = fit::readRecording(r);
  fit::separate(s.rest, r.table, r.physics.ball_radius);
  const int evals = std::max(options.evals, kMinFitEvals);
  const fit::Found found =
      fit::searchShot(s, r.physics, evals, options.objective, options.seed, options.cancel);
  ShotFit f = fit::shotFitOf(s, r.physics, found);
  fit::review(s, r.physics, f, {evals, options.objective, options.cancel});
  return f;
}

void reviewFit(const Recording& r, const PhysicsParams& physics, ShotFit& fit, int evals,
               FitObjective objective, const std::atomic<bool>* cancel) {
  const CancelScope scope(cancel);
  fit::RecordedShot s = fit::readRecording(r);
  fit::separate(s.rest, r.table, r.physics.ball_radius);
  fit::review(s, physics, fit, {evals, objective, cancel});
}

std::vector<ShotFit> fitShots(const std::vector<Recording>& shots, const FitOptions& options) {
  std::vector<ShotFit> fits(shots.size());
  std::mutex reporting;
  std::size_t done = 0;
  parallelFor(shots.size(), threadsFor(options.threads), [&](std::size_t i) {
    fits[i] = fitShot(shots[i], options);
    if (!options.progress) return;
    std::lock_guard<std::mutex> lock(reporting);
    options.progress(++done, shots.size());
  });
  return fits;
}

}  // namespace nineball
