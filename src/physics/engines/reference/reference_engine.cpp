#include "physics/engines/reference/reference_engine.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "physics/engines/engine_internals.hpp"
#include "physics/engines/event_loop.hpp"
#include "physics/model/arc_log.hpp"
#include "physics/model/event_queue.hpp"
#include "physics/model/motion.hpp"
#include "physics/model/next_event.hpp"
#include "physics/resolve/cue/cue.hpp"
#include "physics/resolve/resolver.hpp"

namespace nineball::reference {
namespace {

using physics::Kinematics;
using physics::NextEvent;

/// The reference engine ("reference"): the exact event-based solver, with no Box2D and no time
/// step. Between events every ball follows the closed form of its phase; each event (a
/// contact, a phase ending, a pocket) is the root of a polynomial in time, found to full
/// precision, and resolved by the same resolver as the Box2D engine. It is the yardstick the
/// Box2D engine is measured against. Its steps are only where a caller asks it to stop (a
/// frame of the window); a run to rest takes none.
class ReferenceEngine final : public Engine,
                              public physics::EngineInternals,
                              private physics::EngineBalls,
                              private physics::LoopEngine {
 public:
  ReferenceEngine(const TableDef& table, const PhysicsParams& physics, const StepParams& step);

  void addBall(const BallState& b) override {
    Ball ball;
    ball.state = b;
    ball.state.mass = b.mass.value_or(p_.ball_mass);
    ball.on_table = !b.pocket && !b.off_table;
    if (b.off_table && !ball.state.pocket) ball.state.takeOff(std::nullopt);
    ball.arc = physics::beginArc(run_.time, {b.pos, b.vel, b.w, b.z, b.vz}, p_);
    balls_.push_back(ball);
    if (!logging_) return;
    log_.addBall(b.id);
    if (b.pocket) {
      log_.pocket(balls_.size() - 1, run_.time, b.pos);
    } else {
      logArc(balls_.back());
    }
  }

  bool strike(int ball_id, const Shot& shot) override {
    Ball& b = balls_[indexOf(ball_id)];
    if (!b.on_table)
      throw std::invalid_argument("ball " + std::to_string(ball_id) + " is pocketed");
    // At the arc's own start its centre is the one it was given, to the bit.
    const Vec2 at = b.arc.t0 == run_.time ? b.arc.start.p : now(b).p;
    const auto k = physics::strokeBall(ball_id, run_.time, at, shot, *b.state.mass, p_, events_);
    if (!k) return false;
    b.arc = physics::beginArc(run_.time, *k, p_);
    logArc(b);
    changed(b);
    return true;
  }

  void placeBall(int ball_id, Vec2 pos) override {
    Ball& b = balls_[indexOf(ball_id)];
    b.on_table = true;
    b.state.backOnTable();
    b.state.pos = pos;
    restart(b, physics::Kinematics{pos, {}, {}});
  }

  void step() override {
    const double end = physics::stepBoundary(++run_.steps, sp_.hz);
    if (!run_.exhausted) run(end, false);
    run_.time = end;
  }

  void runFor(double seconds) override {
    const double end = run_.time + seconds;
    run(end, false);
    if (!run_.exhausted) run_.time = end;
  }

  void runUntilRest(const std::function<bool(const std::vector<Event>&)>& stop = {}) override;
  bool stepTowardRest(double deadline) override {
    return physics::stepTowardRest(*this, queue_, run_, sp_.hz, deadline, events_);
  }

  void logArcs() override { logging_ = true; }

  const physics::ArcLog* arcLog() const override { return logging_ ? &log_ : nullptr; }

  bool atRest() const override { return settled(); }
  bool exhausted() const override { return run_.exhausted; }
  const std::string& budgetSpent() const override { return run_.budget_spent; }
  double time() const override { return run_.time; }
  long steps() const override { return run_.steps; }
  std::vector<BallState> balls() const override {
    std::vector<BallState> out;
    out.reserve(balls_.size());
    for (const Ball& b : balls_) {
      BallState s = b.state;
      if (b.on_table) {
        const Kinematics k = now(b);
        s.pos = k.p;
        s.vel = k.v;
        s.w = k.w;
        s.z = k.z;
        s.vz = k.vz;
      } else {
        s.vel = {};
        s.w = {};
        s.z = 0.0;
        s.vz = 0.0;
      }
      out.push_back(s);
    }
    return out;
  }

  const std::vector<Event>& events() const override { return events_; }
  void clearEvents() override { events_.clear(); }
  const TableGeometry& table() const override { return table_; }
  const PhysicsParams& physics() const override { return p_; }
  const StepParams& stepParams() const override { return sp_; }
  physics::SearchWork searchWork() const override { return queue_.work(); }

  void reset() override {
    balls_.clear();
    events_.clear();
    queue_.clear();
    resolver_.reset();
    log_ = physics::ArcLog{};
    logging_ = false;
    run_ = physics::RunState{};
  }

 private:
  struct Ball {
    BallState state;  // id, mass, and where a pocketed ball dropped
    physics::Arc arc;
    bool on_table = true;
  };

  std::size_t indexOf(int id) const {
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      if (balls_[i].state.id == id) return i;
    }
    throw std::invalid_argument("no ball with id " + std::to_string(id));
  }

  // --- the balls as the run loop sees them ---
  std::size_t ballCount() const override { return balls_.size(); }

  bool settled() const override {
    for (const Ball& b : balls_) {
      if (b.on_table && b.arc.translating()) return false;
    }
    return true;
  }

  double describe(std::vector<physics::Mover>& movers, double end) const override {
    movers.clear();
    for (const Ball& b : balls_) movers.push_back({b.on_table ? &b.arc : nullptr, true});
    return end;
  }

  void carry(double) override {}  // the closed forms carry every ball

  void resolve(const NextEvent& e) override { resolver_.resolve(e, *this); }

  // Runs until `end`, or until every ball has stopped when `to_rest`. Every prediction is kept
  // until its balls change, whatever the run's end: a run cut into steps finds the same events,
  // to the bit, as one run.
  void run(double end, bool to_rest) {
    physics::runEvents(*this, queue_, run_, end, to_rest, events_);
  }

  void changed(const Ball& b) { queue_.changed(static_cast<std::size_t>(&b - balls_.data())); }

  bool runOver(double deadline) const {
    return settled() || run_.time >= deadline || run_.exhausted;
  }

  physics::Kinematics now(const Ball& b) const { return physics::stateAt(b.arc, run_.time, p_); }

  void restart(Ball& b, const physics::Kinematics& k) {
    b.arc = physics::beginArc(run_.time, k, p_);
    logArc(b);
    changed(b);
  }

  // Only balls the log knows (a trace was asked for) are logged.
  void logArc(const Ball& b) {
    const auto i = static_cast<std::size_t>(&b - balls_.data());
    if (logging_ && i < log_.ids().size()) log_.record(i, b.arc);
  }

  // --- the balls as the resolver sees them ---
  std::size_t count() const override { return balls_.size(); }
  bool onTable(std::size_t i) const override { return balls_[i].on_table; }
  int id(std::size_t i) const override { return balls_[i].state.id; }
  double mass(std::size_t i) const override { return *balls_[i].state.mass; }
  Vec2 centre(std::size_t i) const override { return now(balls_[i]).p; }
  physics::Kinematics now(std::size_t i) const override { return now(balls_[i]); }
  const physics::Arc& arc(std::size_t i) const override { return balls_[i].arc; }
  void restart(std::size_t i, const physics::Kinematics& k) override { restart(balls_[i], k); }

  void nextPhase(std::size_t i) override {
    balls_[i].arc = physics::nextArc(balls_[i].arc, p_);
    logArc(balls_[i]);
    queue_.changed(i);
  }

  void drop(std::size_t i, std::optional<PocketId> pocket) override {
    Ball& a = balls_[i];
    a.state.pos = now(a).p;
    a.state.takeOff(pocket);
    a.on_table = false;
    queue_.changed(i);
    if (i < log_.ids().size()) log_.pocket(i, run_.time, a.state.pos);
  }

  PhysicsParams p_;
  StepParams sp_;
  TableGeometry table_;
  physics::EventSearch search_;
  std::vector<Ball> balls_;
  std::vector<Event> events_;
  physics::Resolver resolver_;
  physics::EventQueue queue_{search_};
  physics::ArcLog log_;  // filled only once logArcs() has been called
  bool logging_ = false;
  physics::RunState run_;
};

ReferenceEngine::ReferenceEngine(const TableDef& table, const PhysicsParams& physics,
                                 const StepParams& step)
    : p_(physics),
      sp_(step),
      table_(buildTable(table, p_.ball_radius)),
      search_(table_, p_),
      resolver_(p_, table_, search_.cushions, events_) {}

void ReferenceEngine::runUntilRest(const std::function<bool(const std::vector<Event>&)>& stop) {
  const double deadline = run_.time + sp_.max_time;
  if (!stop) {
    // Nothing to look at between steps: one run, which takes no step (see run()).
    run(deadline, true);
  } else {
    while (!runOver(deadline)) {
      stepTowardRest(deadline);
      if (stop(events_)) return;
    }
  }
  physics::noteStillMoving(*this, run_, sp_.max_time);
}

}  // namespace

physics::EngineDef referenceEngine() {
  physics::EngineDef e;
  e.name = "reference";
  e.make = [](const TableDef& table, const PhysicsParams& physics,
              const StepParams& step) -> std::unique_ptr<Engine> {
    return std::make_unique<ReferenceEngine>(table, physics, step);
  };
  e.lacks = "has no time step and no Box2D";
  return e;
}

}  // namespace nineball::reference
