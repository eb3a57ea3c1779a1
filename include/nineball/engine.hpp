#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/event.hpp"
#include "nineball/params.hpp"
#include "nineball/shot.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// The physics of one table, run by one of the engines of the registry
/// (src/physics/engines/registry.cpp), made by makeEngine from StepParams::engine. Both
/// engines follow the same models (src/physics/resolve); they differ in how they find the next
/// event and move the balls to it. Everything here is SI.
class Engine {
 public:
  Engine() = default;
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;
  virtual ~Engine() = default;

  /// Adds a ball. Ids must be unique; the caller checks that it fits on the table.
  virtual void addBall(const BallState& ball) = 0;
  /// Gives the cue ball (or any ball) the velocity and spin of a shot. A tip offset beyond
  /// PhysicsParams::miscue_limit is a miscue: a Miscue event, the ball stays still, false.
  virtual bool strike(int ball_id, const Shot& shot) = 0;
  /// Puts a ball at `pos` at rest: a ball on the table is moved (ball in hand), a pocketed
  /// one comes back (spotting).
  virtual void placeBall(int ball_id, Vec2 pos) = 0;

  /// Advances one fixed step of 1/hz seconds; appends what happened to events().
  virtual void step() = 0;
  /// Runs until every ball rests or `seconds` of simulated time have passed.
  virtual void runFor(double seconds) = 0;
  /// Runs until every ball rests, for at most StepParams::max_time from now; with `stop`,
  /// also until it says, after a step, that what has happened (events()) decides all the
  /// caller needs. It is stepTowardRest() in a row, to a deadline max_time from now.
  virtual void runUntilRest(const std::function<bool(const std::vector<Event>&)>& stop = {}) = 0;
  /// One step of a run to rest: on to the next fixed step's end, or less when every ball comes
  /// to rest within it, or when `deadline` (s, the engine's time) comes first. A run stepped
  /// this way frame by frame (the window) ends bit for bit where runUntilRest ends. True once
  /// the run is over: every ball rests, the deadline is reached or the work budget is spent.
  virtual bool stepTowardRest(double deadline) = 0;

  virtual bool atRest() const = 0;
  /// True once the run has spent its work budget: nothing moves any more, and what the engine
  /// holds is a partial result.
  virtual bool exhausted() const = 0;
  /// Which work budget ran out, for a message ("2000000 contacts", ...); empty while none has.
  virtual const std::string& budgetSpent() const = 0;
  virtual double time() const = 0;
  /// Fixed steps taken (0 for an engine that needs none to run to rest).
  virtual long steps() const = 0;

  /// All balls in the order they were added, pocketed ones included.
  virtual std::vector<BallState> balls() const = 0;
  virtual const std::vector<Event>& events() const = 0;
  virtual void clearEvents() = 0;

  virtual const TableGeometry& table() const = 0;
  virtual const PhysicsParams& physics() const = 0;
  virtual const StepParams& stepParams() const = 0;
  /// Every ball, event and arc log removed and the clock back at zero: the engine is then what
  /// makeEngine made, to the bit, without building its table again (the planner's thousands of
  /// candidates reuse one engine per thread).
  virtual void reset() = 0;
};

/// The engine `step.engine` names, for this table and these settings.
std::unique_ptr<Engine> makeEngine(const TableDef& table, const PhysicsParams& physics,
                                   const StepParams& step);

}  // namespace nineball
