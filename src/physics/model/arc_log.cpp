#include "physics/model/arc_log.hpp"

#include <algorithm>
#include <cmath>

#include "common/limits.hpp"

namespace nineball {

const char* tracePhaseName(TracePhase p) {
  // Part of the JSON contract: spelled here, not borrowed from the physics' names.
  switch (p) {
    case TracePhase::Sliding:
      return "sliding";
    case TracePhase::Rolling:
      return "rolling";
    case TracePhase::Spinning:
      return "spinning";
    case TracePhase::Rest:
      return "rest";
    case TracePhase::Pocketed:
      return "pocketed";
    case TracePhase::Airborne:
      return "airborne";
  }
  return "?";
}

namespace physics {

TracePhase tracePhase(Phase p) {
  switch (p) {
    case Phase::Sliding:
      return TracePhase::Sliding;
    case Phase::Rolling:
      return TracePhase::Rolling;
    case Phase::Spinning:
      return TracePhase::Spinning;
    case Phase::Airborne:
      return TracePhase::Airborne;
    case Phase::Rest:
      break;
  }
  return TracePhase::Rest;
}

namespace {

// The instants every ball is sampled at, sorted and distinct, at most `most` of them (the
// earliest); `truncated` says whether any were left out.
std::vector<double> instants(const ArcLog& log, const std::vector<Event>& events, double end,
                             const TraceRequest& request, std::size_t most, bool& truncated) {
  std::vector<double> ts;
  for (const Event& e : events) ts.push_back(e.t);
  if (!request.events_only) {
    // No more grid points than could be kept: the earliest `most` of the union are among the
    // earliest `most` of each part.
    const double last = std::floor(end * request.hz);
    for (std::size_t k = 0; k <= most && static_cast<double>(k) <= last; ++k) {
      ts.push_back(static_cast<double>(k) / request.hz);
    }
    for (std::size_t b = 0; b < log.ids().size(); ++b) {
      for (const ArcLog::Entry& e : log.entries(b)) ts.push_back(e.arc.t0);
    }
    ts.push_back(end);
  }
  const double cut = log.cut();
  truncated = false;
  ts.erase(std::remove_if(ts.begin(), ts.end(),
                          [&](double t) {
                            if (t >= cut) truncated = true;
                            return !(t >= 0.0 && t <= end && t < cut);
                          }),
           ts.end());
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  if (ts.size() > most) {
    ts.resize(most);
    truncated = true;
  }
  return ts;
}

BallTrace sampleBall(const std::vector<ArcLog::Entry>& entries, const std::vector<double>& ts,
                     const PhysicsParams& p) {
  BallTrace out;
  if (entries.empty()) return out;
  out.t.reserve(ts.size());
  out.x.reserve(ts.size());
  out.y.reserve(ts.size());
  out.vx.reserve(ts.size());
  out.vy.reserve(ts.size());
  out.w.reserve(ts.size());
  out.phase.reserve(ts.size());
  std::size_t current = 0;
  Arc arc = entries.front().arc;
  for (double t : ts) {
    bool moved_on = false;
    while (current + 1 < entries.size() && entries[current + 1].arc.t0 <= t) {
      ++current;
      moved_on = true;
    }
    const ArcLog::Entry& e = entries[current];
    if (moved_on) arc = e.arc;
    Kinematics k;
    TracePhase phase = TracePhase::Pocketed;
    if (e.pocketed) {
      k.p = e.arc.start.p;
    } else {
      // An arc that ended by itself with nothing logged after it (the run stopped first)
      // goes on into the phases that follow it, as the engines would.
      for (int guard = 0; t > arc.end() && guard < 8; ++guard) arc = nextArc(arc, p);
      k = stateAt(arc, t, p);
      phase = tracePhase(arc.phase);
    }
    out.t.push_back(t);
    out.x.push_back(k.p.x);
    out.y.push_back(k.p.y);
    out.vx.push_back(k.v.x);
    out.vy.push_back(k.v.y);
    out.z.push_back(k.z);
    out.vz.push_back(k.vz);
    out.w.push_back(k.w);
    out.phase.push_back(phase);
  }
  return out;
}

}  // namespace

void ArcLog::addBall(int id) {
  ids_.push_back(id);
  balls_.emplace_back();
}

void ArcLog::record(std::size_t index, const Arc& arc) {
  add(index, {arc, false});
}

void ArcLog::pocket(std::size_t index, double t, Vec2 p) {
  Entry e;
  e.arc.t0 = t;
  e.arc.start.p = p;
  e.pocketed = true;
  add(index, e);
}

void ArcLog::add(std::size_t index, const Entry& e) {
  // Every ball keeps its first arc, so that a trace always has something to start from.
  if (size_ >= limits::kMaxTraceSamples && !balls_[index].empty()) {
    cut_ = std::min(cut_, e.arc.t0);
    return;
  }
  balls_[index].push_back(e);
  ++size_;
}

Trace sampleTrace(const ArcLog& log, const std::vector<Event>& events, double end,
                  const TraceRequest& request, const PhysicsParams& p) {
  Trace trace;
  const std::size_t count = log.ids().size();
  if (count == 0) return trace;
  const std::size_t most = limits::kMaxTraceSamples / count;
  const std::vector<double> ts = instants(log, events, end, request, most, trace.truncated);
  for (std::size_t b = 0; b < count; ++b) {
    BallTrace bt = sampleBall(log.entries(b), ts, p);
    bt.id = log.ids()[b];
    trace.balls.push_back(std::move(bt));
  }
  return trace;
}

}  // namespace physics
}  // namespace nineball
