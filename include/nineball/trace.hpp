#pragma once

#include <vector>

#include "nineball/vec3.hpp"

namespace nineball {

/// What a trace samples: every ball at the same instants, taken from the closed form each
/// ball follows between events (never interpolated between steps). With `hz` the instants are
/// every 1/hz s from 0 to the end of the run, every event's instant and every instant at which
/// a ball's phase changes (sliding to rolling, to spinning, to rest), and the end; with
/// `events_only` the distinct instants of the result's events alone.
struct TraceRequest {
  double hz = 0.0;  ///< samples per second (limits::kMinTraceHz-kMaxTraceHz); 0 with events_only
  bool events_only = false;
};

/// What the cloth is doing to a ball at a sample, or that it has dropped.
enum class TracePhase { Sliding, Rolling, Spinning, Rest, Pocketed, Airborne };

/// "sliding", "rolling", "spinning", "rest", "pocketed" or "airborne".
const char* tracePhaseName(TracePhase p);

/// One ball's samples, index by index. At an instant where the motion changes (an event),
/// the velocity, spin and phase are those just after it. A pocketed ball stays where its
/// centre entered the drop circle, at rest, phase Pocketed.
struct BallTrace {
  int id = 0;
  std::vector<double> t;  ///< s
  std::vector<double> x, y;
  std::vector<double> vx, vy;
  std::vector<double> z, vz;  ///< m and m/s: the height above resting on the cloth, and its speed
  std::vector<Vec3> w;        ///< rad/s
  std::vector<TracePhase> phase;

  std::size_t size() const { return t.size(); }
};

/// Every ball's samples, in the scene's order of balls.
struct Trace {
  std::vector<BallTrace> balls;
  /// True when the run needed more than limits::kMaxTraceSamples samples (balls x instants):
  /// the trace then holds the earliest instants that fit, and ends there.
  bool truncated = false;
};

}  // namespace nineball
