#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "nineball/motion.hpp"
#include "physics/model/arc_log.hpp"
#include "physics/model/contact_times.hpp"
#include "physics/model/motion.hpp"

namespace nineball {
namespace {

physics::Kinematics kinematicsOf(const BallState& b) {
  return {b.pos, b.vel, b.w, b.z, b.vz};
}

// The arc the ball follows at time t, from the one that starts at `arc`.
physics::Arc arcAt(physics::Arc arc, double t, const PhysicsParams& p) {
  while (arc.end() <= t && arc.phase != physics::Phase::Rest) arc = physics::nextArc(arc, p);
  return arc;
}

}  // namespace

BallState freeMotion(const BallState& ball, double t, const PhysicsParams& p) {
  if (!(t >= 0.0) || !std::isfinite(t)) throw std::invalid_argument("freeMotion: t must be >= 0");
  const physics::Arc arc = arcAt(physics::beginArc(0.0, kinematicsOf(ball), p), t, p);
  const physics::Kinematics k = physics::stateAt(arc, t, p);
  BallState out = ball;
  out.pos = k.p;
  out.vel = k.v;
  out.w = k.w;
  out.z = k.z;
  out.vz = k.vz;
  return out;
}

TracePhase freePhase(const BallState& ball, const PhysicsParams& p) {
  return physics::tracePhase(physics::beginArc(0.0, kinematicsOf(ball), p).phase);
}

BallState tracedState(const BallTrace& b, double t, const PhysicsParams& p) {
  const auto after = std::upper_bound(b.t.begin(), b.t.end(), t);
  const std::size_t k =
      after == b.t.begin() ? 0 : static_cast<std::size_t>(after - b.t.begin()) - 1;
  BallState s;
  s.id = b.id;
  s.pos = {b.x[k], b.y[k]};
  if (b.phase[k] == TracePhase::Pocketed) return s;
  s.vel = {b.vx[k], b.vy[k]};
  s.w = b.w[k];
  return t > b.t[k] ? freeMotion(s, t - b.t[k], p) : s;
}

std::optional<double> timeToTouch(const BallState& a, const BallState& b, const PhysicsParams& p,
                                  double horizon) {
  if (!(horizon >= 0.0) || !std::isfinite(horizon)) {
    throw std::invalid_argument("timeToTouch: the horizon must be finite and >= 0");
  }
  const physics::Clock clock = physics::Clock::of(p);
  physics::Arc arc_a = physics::beginArc(0.0, kinematicsOf(a), p);
  physics::Arc arc_b = physics::beginArc(0.0, kinematicsOf(b), p);
  // Piece by piece, while both balls keep one closed form each.
  for (double t = 0.0; t < horizon;) {
    const double end = std::min({arc_a.end(), arc_b.end(), horizon});
    const physics::Path pa = physics::pathFrom(arc_a, t, p);
    const physics::Path pb = physics::pathFrom(arc_b, t, p);
    const auto s = physics::ballContact(pa, pb, 2.0 * p.ball_radius, clock.fromTime(end - t));
    if (s) return t + clock.toTime(*s);
    if (arc_a.phase == physics::Phase::Rest && arc_b.phase == physics::Phase::Rest) break;
    t = end;
    arc_a = arcAt(arc_a, t, p);
    arc_b = arcAt(arc_b, t, p);
  }
  return std::nullopt;
}

}  // namespace nineball
