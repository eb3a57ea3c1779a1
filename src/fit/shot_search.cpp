#include "fit/shot_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/log.hpp"
#include "fit/nelder_mead.hpp"
#include "nineball/random.hpp"
#include "physics/model/slate.hpp"

namespace nineball::fit {
namespace {

constexpr double kDegree = kPi / 180.0;

// First steps of the simplex: a first guess (from the samples) is this far off at most...
const Variables kCoarseStep{1.0 * kDegree, 0.05, 0.15, 0.15, 3.0 * kDegree, 0.01};
// ... and a fitted shot about this far.
const Variables kFineStep{0.2 * kDegree, 0.01, 0.04, 0.04, 1.0 * kDegree, 0.003};

// The scan of the cue ball's heading: every 5 degrees at six speeds about the first guess,
// the best kScanKept at least kScanApart apart searched on, over the cue ball up to kCueWindow
// past its first recorded event.
constexpr int kScanHeadings = 72;
constexpr double kScanSpeeds[] = {0.5, 0.7, 1.0, 1.4, 2.0, 2.8};
constexpr std::size_t kScanKept = 3;
constexpr double kScanApart = 4.0 * kPi / 180.0;
constexpr double kCueWindow = 0.1;

// Tips the search starts from: the centre and eight about it.
constexpr double kTipStart = 0.3;

// After the cue ball's first event, the window the starting tips are judged over (s); then
// ever longer windows, each fitting the best of the last again and keeping half of them
// (successive halving), the whole shot (infinity) last.
constexpr double kFirstWindow = 1.0;
constexpr double kLongerWindows[] = {2.0, 4.0, std::numeric_limits<double>::infinity()};

// The searches each stage may run, as shares of the budget.
constexpr double kCueShare = 0.05;
constexpr double kTipShare = 0.025;    // each of the nine starting tips
constexpr double kWindowShare = 0.11;  // each longer window, shared by the shots it keeps
constexpr double kLevelShare = 0.6;    // of what is left: the places, the cue level
// A jump is far from any level fit (the cue ball flies, lands and hops): where balls may leave
// the cloth, searches from these raised cues, each with the level fit's speed on the table, take
// kJumpShare of what the elevation's restarts would have.
constexpr double kJumpStartsDeg[] = {25.0, 40.0, 55.0};
constexpr double kJumpShare = 0.4;
constexpr double kJumpStartShare = 0.08;  // of that, each start's first fit
// The flight and the landing after it: the window a jump's stroke is first fitted over (s past
// the cue ball's first recorded event).
constexpr double kJumpWindow = 0.5;
// Searches whose errors lie within this factor of the best go on to the next window.
constexpr double kClose = 1.2;

class Search {
 public:
  Search(const RecordedShot& s, const PhysicsParams& p, int budget, const std::atomic<bool>* cancel)
      : s_(s), p_(p), budget_(budget), cancel_(cancel) {}

  int left() const { return budget_ - used_; }
  int used() const { return used_; }

  // Searches the variables `free` from x (the others held), at most `budget` simulations.
  Found over(const std::vector<int>& free, const Variables& x, const Variables& step,
             const Window& w, int budget) {
    budget = std::min(budget, left());
    if (budget <= 0) return {x, error(x, w), 0};
    std::vector<double> x0, steps;
    for (int i : free) {
      x0.push_back(x[i]);
      steps.push_back(step[i]);
    }
    auto widen = [&](const std::vector<double>& sub) {
      Variables full = x;
      for (std::size_t k = 0; k < free.size(); ++k) full[free[k]] = sub[k];
      return full;
    };
    const Minimum m = nelderMead(
        [&](const std::vector<double>& sub) { return searchError(s_, p_, widen(sub), w); }, x0,
        steps, budget, 1e-3, cancel_);
    used_ += m.evals;
    const Variables y = legal(s_, p_, widen(m.x));
    logger("fit")->debug(
        "{}: window to {:.2f} s, {} variables, {} runs: {:.4f} m (heading {:.3f} deg, speed "
        "{:.3f}, tip {:.3f} {:.3f}, elevation {:.2f} deg, strike {:.4f} s)",
        s_.recording->id, w.until, free.size(), m.evals, m.f, y[kHeading] / kDegree, y[kSpeed],
        y[kSide], y[kHeight], y[kElevation] / kDegree, y[kStrike]);
    return {y, m.f, m.evals};
  }

  double error(const Variables& x, const Window& w) {
    ++used_;
    return searchError(s_, p_, x, w);
  }

 private:
  const RecordedShot& s_;
  const PhysicsParams& p_;
  int budget_;
  const std::atomic<bool>* cancel_;
  int used_ = 0;
};

// A level cue first: a slight elevation (swerve) trades against the heading within a
// tracker's noise, so it is kept only where it lowers the error by more than kElevationGain.
const std::vector<int> kLevel{kHeading, kSpeed, kSide, kHeight, kStrike};
constexpr double kElevationGain = 0.05;
// A ball's place at the strike is known to about a millimetre from its samples before it.
constexpr double kPlaceStep = 0.002;

// The shot's variables and the balls' places, the elevation among them or not.
std::vector<int> everything(const Variables& x, bool elevation) {
  std::vector<int> all;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (elevation || i != kElevation) all.push_back(static_cast<int>(i));
  }
  return all;
}

Variables stepsFor(const Variables& x, const Variables& shot_steps) {
  Variables steps = shot_steps;
  steps.resize(x.size(), kPlaceStep);
  return steps;
}

Window after(const RecordedShot& s, double seconds) {
  Window w;
  w.until = s.first_event + seconds;
  return w;
}

// The same shot twice: within a fine step of each other in every variable of the shot.
bool alike(const Found& a, const Found& b) {
  for (int i = 0; i < kVariables; ++i) {
    if (std::abs(a.x[i] - b.x[i]) > kFineStep[i]) return false;
  }
  return true;
}

// Of ranked searches, those worth a longer window: no two alike, and every one whose error
// is within kClose of the best (a window too short to tell them apart), at least half.
void keepTheBest(std::vector<Found>& ranked) {
  std::vector<Found> kept;
  for (const Found& f : ranked) {
    bool seen = false;
    for (const Found& k : kept) seen = seen || alike(f, k);
    if (!seen) kept.push_back(f);
  }
  const std::size_t half = (kept.size() + 1) / 2;
  std::size_t n = 0;
  while (n < kept.size() && (n < half || kept[n].error <= kClose * kept.front().error)) ++n;
  kept.resize(n);
  ranked = kept;
}

int share(int budget, double part) {
  return std::max(1, static_cast<int>(std::lround(budget * part)));
}

}  // namespace

namespace {

void rank(std::vector<Found>& found) {
  std::stable_sort(found.begin(), found.end(),
                   [](const Found& a, const Found& b) { return a.error < b.error; });
}

// The cue ball's heading, speed and strike. The first guess from the samples is wrong where
// the cue ball met a cushion within a frame or two: headings all round it, at six speeds,
// judged on the cue ball alone a little past its first event, and the best few searched there.
Variables cueBallAlone(const RecordedShot& s, Search& search, int evals) {
  Window cue = after(s, kCueWindow);
  cue.cue_only = true;
  std::vector<Found> scanned;
  for (int k = 0; k < kScanHeadings; ++k) {
    for (double scale : kScanSpeeds) {
      // Struck when this speed would have carried the ball to its first sample in motion.
      const double speed = s.speed * scale;
      Variables x{s.heading + 2.0 * kPi * k / kScanHeadings,
                  speed,
                  0.0,
                  0.0,
                  0.0,
                  std::clamp(s.cue_onset - s.cue_first_move / speed, s.earliest, s.latest)};
      scanned.push_back({x, search.error(x, cue), 1});
    }
  }
  rank(scanned);
  std::vector<Found> cues;
  for (const Found& f : scanned) {
    bool near = false;
    for (const Found& c : cues) {
      near =
          near || std::abs(std::remainder(f.x[kHeading] - c.x[kHeading], 2.0 * kPi)) < kScanApart;
    }
    if (!near) cues.push_back(f);
    if (cues.size() == kScanKept) break;
  }
  Found guess;
  guess.error = std::numeric_limits<double>::infinity();
  for (const Found& c : cues) {
    const Found f = search.over({kHeading, kSpeed, kStrike}, c.x, kCoarseStep, cue,
                                share(evals, kCueShare) / static_cast<int>(kScanKept));
    if (f.error < guess.error) guess = f;
  }
  return guess.x;
}

// Nine tips about the cue ball's stroke, each searched over the first second after its first
// event, then ever longer windows, the leaders kept (keepTheBest); the best of the whole shot.
Found bestTip(const RecordedShot& s, Search& search, const Variables& cue, int evals,
              FitObjective objective) {
  std::vector<Found> starts;
  for (double side : {0.0, -kTipStart, kTipStart}) {
    for (double height : {0.0, -kTipStart, kTipStart}) {
      Variables from = cue;
      from[kSide] = side;
      from[kHeight] = height;
      starts.push_back(
          search.over(kLevel, from, kCoarseStep, after(s, kFirstWindow), share(evals, kTipShare)));
    }
  }
  rank(starts);
  for (double seconds : kLongerWindows) {
    keepTheBest(starts);
    const int each = share(evals, kWindowShare) / static_cast<int>(starts.size());
    const Window w = std::isinf(seconds) ? wholeShot(objective) : after(s, seconds);
    for (Found& f : starts) f = search.over(kLevel, f.x, kFineStep, w, each);
    rank(starts);
  }
  return starts.front();
}

// A jump struck at `elevation` from the recording's own first guess (its heading, and its first
// speed on the table, which a ball in the air keeps: the cue's speed is that over
// cos(elevation)), the tip at the centre (below it a raised tip scoops the ball): heading,
// speed, elevation and strike fitted to the cue ball over its flight and landing, and judged
// over the whole shot. `places`: the balls' places at the strike.
Found jumpStart(const RecordedShot& s, const PhysicsParams& p, Search& search,
                const Variables& places, double elevation, const Window& whole, int budget) {
  Variables x = places;
  x[kHeading] = s.heading;
  x[kSpeed] = s.speed / std::cos(elevation);
  x[kSide] = 0.0;
  x[kHeight] = 0.0;
  x[kElevation] = elevation;
  x[kStrike] = std::clamp(s.cue_onset - s.cue_first_move / s.speed, s.earliest, s.latest);
  Window flight = after(s, kJumpWindow);
  flight.cue_only = true;
  Found f = search.over({kHeading, kSpeed, kElevation, kStrike}, legal(s, p, x), kCoarseStep,
                        flight, budget);
  f.error = search.error(f.x, whole);
  return f;
}

// The balls' places join the shot, and restarts about the best, each from a point a fine step
// or so away, spend the rest of the budget: most with a level cue, then with the elevation,
// kept only where it lowers the error by more than kElevationGain.
Found placesAndRestarts(const RecordedShot& s, const PhysicsParams& p, Search& search, Found best,
                        FitObjective objective, std::uint64_t seed,
                        const std::atomic<bool>* cancel) {
  const Window whole = wholeShot(objective);
  best.x = withPlaces(s, best.x);
  const Variables steps = stepsFor(best.x, kFineStep);
  std::uint64_t state = seed;
  auto restarts = [&](Found from, bool elevation, int budget) {
    const int until = search.left() - budget;
    while (search.left() - until > 2 * static_cast<int>(from.x.size()) &&
           !(cancel && cancel->load())) {
      Variables near = from.x;
      for (int i : everything(near, elevation)) {
        if (i < kVariables) near[i] += 0.5 * steps[i] * gaussian(state);
      }
      const Found f = search.over(everything(near, elevation), legal(s, p, near), steps, whole,
                                  search.left() - until);
      if (f.error < from.error) from = f;
    }
    return from;
  };
  best = restarts(best, false, static_cast<int>(kLevelShare * search.left()));
  const bool jumps = physics::airborneAllowed(p);
  Found raised =
      restarts(best, true, static_cast<int>((jumps ? 1.0 - kJumpShare : 1.0) * search.left()));
  if (jumps) {
    // The jump starts judged over the whole shot; the best of them searched on.
    const int each = static_cast<int>(kJumpStartShare * search.left());
    Found jump;
    jump.error = std::numeric_limits<double>::infinity();
    for (double degrees : kJumpStartsDeg) {
      const Found f = jumpStart(s, p, search, best.x, degrees * kDegree, whole, each);
      if (f.error < jump.error) jump = f;
    }
    jump = search.over(everything(jump.x, true), jump.x, steps, whole, search.left() / 2);
    jump = restarts(jump, true, search.left());
    if (jump.error < raised.error) raised = jump;
  }
  return raised.error < (1.0 - kElevationGain) * best.error ? raised : best;
}

}  // namespace

Found searchShot(const RecordedShot& s, const PhysicsParams& p, int evals, FitObjective objective,
                 std::uint64_t seed, const std::atomic<bool>* cancel) {
  Search search(s, p, evals, cancel);
  const Variables cue = cueBallAlone(s, search, evals);
  const Found tip = bestTip(s, search, cue, evals, objective);
  Found best = placesAndRestarts(s, p, search, tip, objective, seed, cancel);
  best.evals = search.used();
  return best;
}

Found refineShot(const RecordedShot& s, const PhysicsParams& p, const Variables& from, int evals,
                 FitObjective objective, const std::atomic<bool>* cancel) {
  Search search(s, p, evals, cancel);
  const bool elevation = from[kElevation] > 0.0;
  Found best = search.over(everything(from, elevation), from, stepsFor(from, kFineStep),
                           wholeShot(objective), evals);
  best.evals = search.used();
  return best;
}

ShotFit shotFitOf(const RecordedShot& s, const PhysicsParams& p, const Found& f) {
  ShotFit fit;
  fit.id = s.recording->id;
  fit.scene = sceneOf(s, p, legal(s, p, f.x), wholeShot(FitObjective::Full));
  fit.scene.until.reset();
  fit.scene.trace.reset();
  // Headings searched past a half turn read as the same direction in (-180, 180] degrees.
  fit.scene.shot->heading_rad = -std::remainder(-fit.scene.shot->heading_rad, 2.0 * kPi);
  for (std::size_t k : s.order) fit.names.push_back(s.recording->balls[k].name);
  fit.strike_time = f.x[kStrike];
  fit.rmse = fitErrors(*s.recording, fit.scene, fit.names, fit.strike_time);
  fit.evals = f.evals;
  return fit;
}

}  // namespace nineball::fit
