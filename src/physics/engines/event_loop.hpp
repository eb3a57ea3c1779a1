#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "nineball/event.hpp"
#include "physics/model/event_queue.hpp"
#include "physics/model/next_event.hpp"

namespace nineball::physics {

/// Where an engine's runs stand: its clock, its fixed steps, and its work budget.
struct RunState {
  double time = 0.0;          ///< s, the engine's clock
  long steps = 0;             ///< fixed steps of 1/hz taken
  long pieces = 0;            ///< stretches of time between events (Box2D steps in that engine)
  long resolved = 0;          ///< events resolved
  bool exhausted = false;     ///< the work budget ran out (or the run was cancelled): nothing moves
  std::string budget_spent;   ///< which budget, for the message
  std::vector<Mover> movers;  ///< kept from event to event: no allocation per event
};

/// What an engine lends the one run loop both engines share (runEvents).
class LoopEngine {
 public:
  /// Called as a run begins (the Box2D engine brings its sensors up to date).
  virtual void beginRun() {}
  /// The balls, pocketed ones included.
  virtual std::size_t ballCount() const = 0;
  /// No ball on the table travels (spins may still die away).
  virtual bool settled() const = 0;
  /// Fills `movers` with each ball as the event search sees it, and returns the latest time
  /// the next piece of the run may end at, `end` or sooner.
  virtual double describe(std::vector<Mover>& movers, double end) const = 0;
  /// Carries the balls over the `dt` seconds before the next event (the Box2D engine moves its
  /// bodies; the reference engine's closed forms need nothing).
  virtual void carry(double dt) = 0;
  /// Resolves `e` at its time, through the resolver.
  virtual void resolve(const NextEvent& e) = 0;

 protected:
  ~LoopEngine() = default;
};

/// The run loop of both engines: from `run.time` to `end`, or until every ball stops when
/// `to_rest`, each next event `queue` finds resolved by `engine` in turn. It stops early when
/// the work budget is spent (limits::kMaxEvents events, limits::kMaxPieces pieces, or more
/// events in a sixtieth of a second than a frozen cluster's loop would leave) or the run is
/// cancelled, and says so in `run`; the moment the last ball stops, an AllAtRest event.
void runEvents(LoopEngine& engine, EventQueue& queue, RunState& run, double end, bool to_rest,
               std::vector<Event>& events);

/// One fixed step of a run to rest (1/hz, or less to `deadline`); true once the run is over:
/// every ball still, the deadline reached or the budget spent.
bool stepTowardRest(LoopEngine& engine, EventQueue& queue, RunState& run, double hz,
                    double deadline, std::vector<Event>& events);

/// The end of fixed step `n` (s).
inline double stepBoundary(long n, double hz) {
  return static_cast<double>(n) / hz;
}

/// Logs a run to rest that stopped at its deadline with balls still moving.
void noteStillMoving(const LoopEngine& engine, const RunState& run, double max_time);

}  // namespace nineball::physics
