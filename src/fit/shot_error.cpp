#include "fit/shot_error.hpp"

#include <algorithm>
#include <cmath>

#include "common/limits.hpp"
#include "nineball/motion.hpp"

namespace nineball::fit {
namespace {

// The early objective's window after the strike (s) and the cue ball's weight in it.
constexpr double kEarlyHorizon = 4.0;
constexpr double kEarlyCueWeight = 1.5;
constexpr double kMaxElevation = 60.0 * kPi / 180.0;  // the steepest jump a cue plays
// Inside the miscue limit by this share, so that a tip on the search's edge still strikes.
constexpr double kTipMargin = 0.95;
// How far a searched place may stray from where the samples put the ball (m): a tracker
// places a ball at rest to a few millimetres, and a search left free trades centimetres of a
// ball's place, which a few samples at rest barely see, against a better fit of a chaotic end.
constexpr double kPlaceReach = 0.01;

Vec2 withinReach(Vec2 place, Vec2 recorded) {
  const Vec2 d = place - recorded;
  const double far = length(d);
  return far > kPlaceReach ? recorded + d * (kPlaceReach / far) : place;
}

}  // namespace

Window wholeShot(FitObjective objective) {
  Window w;
  w.weighting = objective;
  return w;
}

Variables withPlaces(const RecordedShot& s, Variables x) {
  x.resize(kVariables);
  const Variables shot = x;
  for (std::size_t i = 0; i < s.rest.size(); ++i) {
    const Vec2 p = placeOf(s, shot, i);
    x.push_back(p.x);
    x.push_back(p.y);
  }
  return x;
}

Vec2 recordedPlace(const RecordedShot& s, const Variables& x, std::size_t i) {
  return i == 0 ? s.cueAtStrike(x[kStrike]) : s.rest[i];
}

Vec2 placeOf(const RecordedShot& s, const Variables& x, std::size_t i) {
  const std::size_t at = kVariables + 2 * i;
  if (x.size() > at + 1) return {x[at], x[at + 1]};
  return recordedPlace(s, x, i);
}

Variables legal(const RecordedShot& s, const PhysicsParams& p, Variables x) {
  x[kStrike] = std::clamp(x[kStrike], s.earliest, s.latest);
  if (x.size() > kVariables) {
    std::vector<Vec2> places;
    for (std::size_t i = 0; i < s.rest.size(); ++i) {
      places.push_back(withinReach(placeOf(s, x, i), recordedPlace(s, x, i)));
    }
    separate(places, s.recording->table, p.ball_radius);
    for (std::size_t i = 0; i < places.size(); ++i) {
      x[kVariables + 2 * i] = places[i].x;
      x[kVariables + 2 * i + 1] = places[i].y;
    }
  }
  x[kSpeed] = std::clamp(x[kSpeed], kMinSpeed, kMaxSpeed);
  const double reach = kTipMargin * p.miscue_limit;
  const double tip = std::hypot(x[kSide], x[kHeight]);
  if (tip > reach) {
    x[kSide] *= reach / tip;
    x[kHeight] *= reach / tip;
  }
  x[kElevation] = std::clamp(x[kElevation], 0.0, kMaxElevation);
  return x;
}

Scene sceneOf(const RecordedShot& s, const PhysicsParams& p, const Variables& x, const Window& w) {
  Scene scene;
  scene.table = s.recording->table;
  scene.physics = p;
  scene.step.engine = EngineKind::named("reference");
  // Apart and on the table whatever the variables say: a scene the engines may run.
  std::vector<Vec2> places;
  for (std::size_t i = 0; i < s.rest.size(); ++i) places.push_back(placeOf(s, x, i));
  separate(places, s.recording->table, p.ball_radius);
  for (std::size_t i = 0; i < places.size(); ++i) {
    scene.balls.push_back(BallState::at(static_cast<int>(i), places[i]));
  }
  Shot shot;
  shot.heading_rad = x[kHeading];
  shot.speed = x[kSpeed];
  shot.tip = {x[kSide], x[kHeight]};
  shot.elevation_rad = x[kElevation];
  scene.shot = shot;
  const double last = std::min(w.until, s.end);
  const double horizon = w.weighting == FitObjective::Early ? kEarlyHorizon : last - x[kStrike];
  scene.until = std::max(std::min(horizon, last - x[kStrike]), kMinRun);
  scene.trace = TraceRequest{limits::kMinTraceHz, false};
  return scene;
}

double windowError(const RecordedShot& s, const Scene& scene, const SimResult& run, double strike,
                   const Window& w) {
  if (!run.trace) return std::numeric_limits<double>::infinity();
  double sum = 0.0;
  double weights = 0.0;
  const std::size_t balls = w.cue_only ? 1 : s.order.size();
  for (std::size_t i = 0; i < balls; ++i) {
    const RecordedPath& b = s.path(i);
    const BallTrace& traced = run.trace->balls[i];
    for (std::size_t k = 0; k < b.t.size() && b.t[k] <= w.until; ++k) {
      const double after = b.t[k] - strike;
      double weight = 1.0;
      if (w.weighting == FitObjective::Early) {
        if (after < 0.0) continue;
        if (after > kEarlyHorizon) break;
        weight = (i == 0 ? kEarlyCueWeight : 1.0) / (1.0 + after);
      }
      const Vec2 simulated =
          after <= 0.0 ? scene.balls[i].pos : tracedState(traced, after, scene.physics).pos;
      const Vec2 d = simulated - Vec2{b.x[k], b.y[k]};
      sum += weight * dot(d, d);
      weights += weight;
    }
  }
  return weights > 0.0 ? std::sqrt(sum / weights) : 0.0;
}

double searchError(const RecordedShot& s, const PhysicsParams& p, const Variables& x,
                   const Window& w) {
  const Variables ok = legal(s, p, x);
  // Outside, the error grows with the distance (in units of a metre, a radian, a second,
  // a tip of R), so that the simplex walks back in.
  double outside = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) outside += (x[i] - ok[i]) * (x[i] - ok[i]);
  const Scene scene = sceneOf(s, p, ok, w);
  const SimResult run = simulate(scene);
  return windowError(s, scene, run, ok[kStrike], w) + std::sqrt(outside);
}

}  // namespace nineball::fit
