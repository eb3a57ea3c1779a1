#pragma once

#include <cstddef>
#include <vector>

#include "nineball/event.hpp"
#include "nineball/params.hpp"
#include "nineball/trace.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

/// Every arc each ball of a run has followed, in time order, for a trace. Both engines write
/// one as they go (each time an event or a phase's end gives a ball a new arc); sampleTrace
/// then reads positions off the closed forms.
class ArcLog {
 public:
  /// One stretch of a ball's motion: the arc from arc.t0 on, or (pocketed) off the table
  /// from arc.t0 on, where arc.start.p says.
  struct Entry {
    Arc arc;
    bool pocketed = false;
  };

  /// A ball joins the run (its index is the next one).
  void addBall(int id);
  /// Ball `index` follows `arc` from arc.t0 on.
  void record(std::size_t index, const Arc& arc);
  /// Ball `index` drops at time t, its centre at p.
  void pocket(std::size_t index, double t, Vec2 p);

  const std::vector<int>& ids() const { return ids_; }
  const std::vector<Entry>& entries(std::size_t index) const { return balls_[index]; }
  /// The first instant the log could not hold (limits::kMaxTraceSamples entries in all);
  /// kNever when it holds the whole run.
  double cut() const { return cut_; }

 private:
  void add(std::size_t index, const Entry& e);

  std::vector<int> ids_;
  std::vector<std::vector<Entry>> balls_;
  std::size_t size_ = 0;
  double cut_ = kNever;
};

/// The name a trace gives a phase of the motion.
TracePhase tracePhase(Phase p);

/// The trace of a run that ended at `end`, sampled as `request` asks from the arcs in `log`;
/// `events` are the run's events (their instants are sampled).
Trace sampleTrace(const ArcLog& log, const std::vector<Event>& events, double end,
                  const TraceRequest& request, const PhysicsParams& p);

}  // namespace nineball::physics
