#pragma once

#include <atomic>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/event.hpp"
#include "nineball/params.hpp"
#include "nineball/shot.hpp"
#include "nineball/table.hpp"
#include "nineball/trace.hpp"

namespace nineball {

/// One headless run: a table, its physics, balls, an optional shot of the cue ball.
struct Scene {
  TableDef table;
  PhysicsParams physics;
  StepParams step;
  std::vector<BallState> balls;
  std::optional<Shot> shot;
  std::optional<double> until;        ///< seconds; empty means "until rest"
  std::optional<TraceRequest> trace;  ///< sample every ball's motion into SimResult::trace
};

/// How a run ended. Rest and Until are complete; MaxTime and Budget are partial results.
enum class SimEnd {
  Rest,     ///< every ball at rest
  Until,    ///< the asked-for time reached
  MaxTime,  ///< step.max_time of simulated time reached with balls still moving
  Budget,   ///< the work budget (limits.hpp) spent with balls still moving
};

/// "rest", "until", "max_time" or "budget".
const char* simEndName(SimEnd end);

/// How a run of either engine ended, from what it was asked for and where it stopped.
SimEnd simEnd(bool until, bool exhausted, bool at_rest);

struct SimResult {
  double time = 0.0;     ///< simulated seconds reached
  long steps = 0;        ///< fixed steps computed
  double wall_ms = 0.0;  ///< wall time of the stepping alone
  std::vector<BallState> balls;
  std::vector<Event> events;
  SimEnd end = SimEnd::Rest;
  std::optional<Trace> trace;  ///< when the scene asked for one
  std::string budget;          ///< which work budget ran out, when end is Budget

  /// True when the run stopped before its end (max_time or the work budget).
  bool partial() const { return end == SimEnd::MaxTime || end == SimEnd::Budget; }
};

/// The most scene text a reader takes, in bytes: the command line's bound on its input.
std::size_t maxSceneBytes();

/// Runs a scene that has already been checked (see validateScene).
SimResult simulate(const Scene& scene);

/// Runs checked scenes on up to `threads` threads (the caller's included; 0 for one per core),
/// each as simulate() runs it alone: the results, in order, do not depend on the threads.
/// With `cancel`, every run stops at its next event once it is raised, and no scene is started
/// after: the results are then unfinished and the caller's to throw away.
std::vector<SimResult> simulateMany(const std::vector<Scene>& scenes, int threads,
                                    const std::atomic<bool>* cancel = nullptr);

/// Empty when the result keeps its promises: every number finite, every ball on the table
/// (its centre inside the cushions) or pocketed. Else what is broken: a defect of the engine,
/// reported as an internal error and never printed as a result. Both engines' results are
/// checked by every command that prints one.
std::optional<std::string> resultFault(const Scene& scene, const SimResult& result);

/// Empty when the scene can be simulated, else a message naming the field and the reason
/// (balls overlapping, off the table, duplicate ids, shot without a cue ball, ...).
std::optional<std::string> validateScene(const Scene& scene);
/// validateScene's checks of the balls and the shot's cue ball alone, on `table` (the scene's
/// table built, once for many scenes that share it; their settings checked once).
std::optional<std::string> validateBalls(const Scene& scene, const TableGeometry& table);

}  // namespace nineball
