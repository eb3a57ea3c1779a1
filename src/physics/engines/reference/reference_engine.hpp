#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "nineball/engine.hpp"
#include "physics/arc_log.hpp"
#include "physics/engines/registry.hpp"
#include "physics/motion.hpp"
#include "physics/next_event.hpp"
#include "physics/resolve/resolver.hpp"

namespace nineball::reference {

/// The reference engine ("reference"): the exact event-based solver, with no Box2D and no time
/// step. Between events every ball follows the closed form of its phase; each event (a
/// contact, a phase ending, a pocket) is the root of a polynomial in time, found to full
/// precision, and resolved by the same resolver as the Box2D engine. It is the yardstick the
/// Box2D engine is measured against. Its steps are only where a caller asks it to stop (a
/// frame of the window); a run to rest takes none.
class ReferenceEngine final : public Engine, private physics::EngineBalls {
 public:
  ReferenceEngine(const TableDef& table, const PhysicsParams& physics, const StepParams& step);

  void addBall(const BallState& ball) override;
  bool strike(int ball_id, const Shot& shot) override;
  void placeBall(int ball_id, Vec2 pos) override;
  void step() override;
  void runFor(double seconds) override;
  void runUntilRest(const std::function<bool(const std::vector<Event>&)>& stop = {}) override;
  bool stepTowardRest(double deadline) override;
  void logArcs() override;
  const physics::ArcLog* arcLog() const override;
  bool atRest() const override { return settled(); }
  bool exhausted() const override { return exhausted_; }
  const std::string& budgetSpent() const override { return budget_spent_; }
  double time() const override { return t_; }
  long steps() const override { return steps_; }
  std::vector<BallState> balls() const override;
  const std::vector<Event>& events() const override { return events_; }
  void clearEvents() override { events_.clear(); }
  const TableGeometry& table() const override { return table_; }
  const PhysicsParams& physics() const override { return p_; }
  const StepParams& stepParams() const override { return sp_; }

 private:
  struct Ball {
    BallState state;  // id, mass, and where a pocketed ball dropped
    physics::Arc arc;
    bool on_table = true;
  };

  std::size_t indexOf(int id) const;
  bool settled() const;
  // Runs until `end`, or until every ball has stopped when `to_rest`. Each event is searched
  // for from the last change up to `horizon`, and kept while it lies beyond `end`: a run cut
  // into steps finds the same events, to the bit, as one run to the same horizon.
  void run(double end, bool to_rest, double horizon);
  // A ball was added, struck or placed: the event kept is void, and the next search starts now.
  void changed();
  double boundary(long n) const;
  bool runOver(double deadline) const;
  physics::Kinematics now(const Ball& b) const;
  void restart(Ball& b, const physics::Kinematics& k);
  void logArc(const Ball& b);

  // --- the balls as the resolver sees them ---
  std::size_t count() const override { return balls_.size(); }
  bool onTable(std::size_t i) const override { return balls_[i].on_table; }
  int id(std::size_t i) const override { return balls_[i].state.id; }
  double mass(std::size_t i) const override { return *balls_[i].state.mass; }
  Vec2 centre(std::size_t i) const override { return now(balls_[i]).p; }
  physics::Kinematics now(std::size_t i) const override { return now(balls_[i]); }
  void restart(std::size_t i, const physics::Kinematics& k) override { restart(balls_[i], k); }

  void nextPhase(std::size_t i) override {
    balls_[i].arc = physics::nextArc(balls_[i].arc, p_);
    logArc(balls_[i]);
  }

  void drop(std::size_t i, PocketId pocket) override {
    Ball& a = balls_[i];
    a.state.pos = now(a).p;
    a.state.pocket = pocket;
    a.on_table = false;
    if (i < log_.ids().size()) log_.pocket(i, t_, a.state.pos);
  }

  PhysicsParams p_;
  StepParams sp_;
  TableGeometry table_;
  physics::EventSearch search_;
  std::vector<Ball> balls_;
  std::vector<Event> events_;
  physics::Resolver resolver_;
  std::vector<physics::Mover> movers_;         // kept from event to event: no allocation per event
  std::optional<physics::NextEvent> pending_;  // found, not yet reached
  double pending_horizon_ = 0.0;
  double from_ = 0.0;    // the time of the last change, where the next search starts
  physics::ArcLog log_;  // filled only once logArcs() has been called
  bool logging_ = false;
  long resolved_ = 0;
  long steps_ = 0;
  bool exhausted_ = false;
  std::string budget_spent_;
  double t_ = 0.0;
};

/// "reference": ReferenceEngine, which reads no field of "step" but max_time.
physics::EngineDef referenceEngine();

}  // namespace nineball::reference
