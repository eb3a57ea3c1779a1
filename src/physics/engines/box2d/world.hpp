#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "nineball/engine.hpp"
#include "physics/engines/engine_internals.hpp"

namespace nineball {

/// The Box2D engine ("box2d"): Box2D bodies for balls, cushions and pockets, advanced in fixed
/// steps, each cut into pieces that end at the next event. Box2D stays behind this interface.
class World final : public Engine, public physics::EngineInternals {
 public:
  World(const TableDef& table, const PhysicsParams& physics, const StepParams& step);
  ~World() override;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Adds a ball. Ids must be unique; the caller checks that it fits on the table.
  void addBall(const BallState& ball) override;
  /// Gives the cue ball (or any ball) the velocity and spin of a shot. A tip offset beyond
  /// PhysicsParams::miscue_limit is a miscue: a Miscue event, the ball stays still, false.
  bool strike(int ball_id, const Shot& shot) override;
  /// Moves a ball that is still on the table (ball in hand, spotting), velocity zero.
  void placeBall(int ball_id, Vec2 pos) override;

  /// Advances one fixed step of 1/hz seconds; appends what happened to events().
  void step() override;
  /// Steps until every ball rests or `seconds` of simulated time have passed.
  void runFor(double seconds) override;
  /// Steps until every ball rests, for at most StepParams::max_time from now; with `stop`,
  /// also until it says, after a step, that what has happened (events()) decides all the
  /// caller needs. It is stepTowardRest() in a row, to a deadline max_time from now.
  void runUntilRest(const std::function<bool(const std::vector<Event>&)>& stop = {}) override;
  /// One step of a run to rest: on to the next fixed step's end, or less when every ball comes
  /// to rest within it, or when `deadline` (s, the world's time) comes first. A run stepped
  /// this way frame by frame (the window) ends bit for bit where runUntilRest ends. True once
  /// the run is over: every ball rests, the deadline is reached or the work budget is spent.
  bool stepTowardRest(double deadline) override;

  /// Keeps every arc each ball follows from here on, for a trace (call before addBall).
  void logArcs() override;
  /// The arcs kept since logArcs(), or null.
  const physics::ArcLog* arcLog() const override;

  bool atRest() const override;
  /// True once the run has spent its work budget (limits::kMaxEvents events, kMaxPieces
  /// pieces, or an endless run of contacts in one step): nothing moves any more, and what the
  /// world holds is a partial result.
  bool exhausted() const override;
  /// Which work budget ran out, for a message: "2000000 contacts", "20000000 pieces", or the
  /// contacts one step may hold. Empty while none has.
  const std::string& budgetSpent() const override;
  double time() const override;
  long steps() const override;

  /// All balls in the order they were added, pocketed ones included.
  std::vector<BallState> balls() const override;
  const std::vector<Event>& events() const override;
  void clearEvents() override;

  const TableGeometry& table() const override;
  const PhysicsParams& physics() const override;
  const StepParams& stepParams() const override;
  physics::SearchWork searchWork() const override;
  void reset() override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

namespace physics {
struct EngineDef;
/// "box2d": World, reading every field of "step".
EngineDef box2dEngine();
}  // namespace physics

}  // namespace nineball
