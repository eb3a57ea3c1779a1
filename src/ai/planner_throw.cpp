#include "ai/planner_throw.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/model/motion.hpp"
#include "physics/resolve/ball_ball/ball_contact.hpp"
#include "physics/resolve/cue/cue.hpp"

namespace nineball::ai {
namespace {

using physics::Arc;
using physics::Kinematics;

// A cue ball still rolling after this long (s) is as good as stopped for aiming.
constexpr double kHorizon = 60.0;
constexpr int kBisections = 60;
// Newton's method: the probe step for the slope, the tolerance and the furthest it may move
// the aim from the ghost ball's (rad).
constexpr double kProbe = 1e-4;
constexpr double kTolerance = 1e-6;
constexpr int kIterations = 8;
constexpr double kMaxCorrection = 8.0 * kPi / 180.0;

double wrapped(double a) {
  return std::remainder(a, 2.0 * kPi);
}

// The cue ball's motion from the strike: each phase's closed form until it stops.
class CuePath {
 public:
  CuePath(const Kinematics& start, const PhysicsParams& p) : p_(p) {
    arcs_.push_back(physics::beginArc(0.0, start, p));
    while (arcs_.back().translating() && arcs_.back().end() < kHorizon && arcs_.size() < 4) {
      arcs_.push_back(physics::nextArc(arcs_.back(), p));
    }
  }
  double end() const {
    double t = 0.0;
    for (const Arc& a : arcs_) {
      if (a.translating()) t = std::min(a.end(), kHorizon);
    }
    return t;
  }
  Kinematics at(double t) const {
    const Arc* arc = &arcs_.front();
    for (const Arc& a : arcs_) {
      if (a.t0 <= t) arc = &a;
    }
    return physics::stateAt(*arc, t, p_);
  }

 private:
  const PhysicsParams& p_;
  std::vector<Arc> arcs_;
};

// The first t in [lo, hi] at which `past` turns true, given it is false at lo and true at hi.
template <class F>
double firstTrue(double lo, double hi, F past) {
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (past(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

std::optional<double> objectDeparture(const PhysicsParams& p, const ThrowSetup& s, double heading) {
  Shot shot = s.shot;
  shot.heading_rad = heading;
  const physics::Strike strike = physics::cueStrike(shot, s.cue_mass, p);
  if (length(strike.v) <= 0.0) return std::nullopt;
  const CuePath path({s.cue, strike.v, strike.w}, p);
  const double touch = 2.0 * p.ball_radius;
  // Closest approach: where the ball stops closing on the object ball (the path is straight
  // or nearly so before a contact), or where it stops.
  auto receding = [&](double t) {
    const Kinematics k = path.at(t);
    return dot(k.v, k.p - s.object) >= 0.0;
  };
  const double end = path.end();
  const double closest = receding(end) ? firstTrue(0.0, end, receding) : end;
  auto touching = [&](double t) { return length(path.at(t).p - s.object) <= touch; };
  if (!touching(closest) || touching(0.0)) return std::nullopt;
  Kinematics a = path.at(firstTrue(0.0, closest, touching));
  Kinematics b{s.object, {}, {}};
  physics::collideBalls(a, b, s.cue_mass, s.object_mass, p);
  if (length(b.v) <= 0.0) return std::nullopt;
  return std::atan2(b.v.y, b.v.x);
}

double headingAllowingForThrow(const PhysicsParams& p, const ThrowSetup& s, double heading,
                               double want_rad) {
  auto error = [&](double h) -> std::optional<double> {
    const auto sent = objectDeparture(p, s, h);
    if (!sent) return std::nullopt;
    return wrapped(*sent - want_rad);
  };
  // Start where the squirted cue ball runs along the ghost ball's line: at a thin cut the
  // squirt alone can miss the object ball.
  const double side = std::clamp(s.shot.tip.x, -1.0, 1.0);
  double h = heading - physics::squirtAngle(side, s.cue_mass, p.cue_end_mass);
  auto e = error(h);
  for (int i = 0; e && i < kIterations; ++i) {
    if (std::abs(*e) < kTolerance) return h;
    const auto probed = error(h + kProbe);
    if (!probed || *probed == *e) break;
    double move = -*e * kProbe / (*probed - *e);
    // Halve a step that misses the ball or makes the error worse.
    bool improved = false;
    for (int halving = 0; halving < 20 && !improved; ++halving, move *= 0.5) {
      const auto next = error(h + move);
      improved = next && std::abs(*next) < std::abs(*e);
      if (improved) {
        h += move;
        e = next;
      }
    }
    if (!improved) break;
    if (std::abs(wrapped(h - heading)) > kMaxCorrection) return heading;
  }
  return e && std::abs(*e) < 1e3 * kTolerance ? h : heading;
}

}  // namespace nineball::ai
