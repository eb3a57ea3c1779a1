#include "reference/reference_engine.hpp"

#include <chrono>
#include <string>
#include <vector>

#include "nineball/limits.hpp"
#include "nineball/log.hpp"
#include "physics/arc_log.hpp"
#include "physics/motion.hpp"
#include "physics/next_event.hpp"
#include "physics/resolve/cue/cue.hpp"
#include "physics/resolve/resolver.hpp"

namespace nineball::reference {
namespace {

using physics::Arc;
using physics::Kinematics;
using physics::NextEvent;

struct Ball {
  BallState state;  // id, mass, and where a pocketed ball dropped
  Arc arc;
  bool on_table = true;
};

class Run final : public physics::EngineBalls {
 public:
  explicit Run(const Scene& scene)
      : p_(scene.physics),
        table_(buildTable(scene.table, p_.ball_radius)),
        search_(table_, p_),
        resolver_(p_, table_, search_.cushions, events_) {
    for (const BallState& b : scene.balls) {
      Ball ball;
      ball.state = b;
      ball.state.mass = b.mass.value_or(p_.ball_mass);
      ball.on_table = !b.pocket;
      ball.arc = physics::beginArc(0.0, {b.pos, b.vel, b.w}, p_);
      balls_.push_back(ball);
      if (!scene.trace) continue;
      log_.addBall(b.id);
      if (b.pocket) {
        log_.pocket(balls_.size() - 1, 0.0, b.pos);
      } else {
        logArc(balls_.back());
      }
    }
  }

  void strike(const Shot& shot) {
    for (Ball& b : balls_) {
      if (b.state.id != kCueBall || !b.on_table) continue;
      if (length(shot.tip) > p_.miscue_limit) {
        Event e;
        e.type = EventType::Miscue;
        e.a = kCueBall;
        events_.push_back(e);
        return;
      }
      const physics::Strike s = physics::cueStrike(shot, *b.state.mass, p_);
      b.arc = physics::beginArc(0.0, {b.arc.start.p, s.v, s.w}, p_);
      logArc(b);
    }
  }

  bool settled() const {
    for (const Ball& b : balls_) {
      if (b.on_table && b.arc.translating()) return false;
    }
    return true;
  }

  // Runs until `end`, or until every ball has stopped when `to_rest`.
  void run(double end, bool to_rest) {
    bool was_settled = settled();
    while (t_ < end && !(to_rest && settled())) {
      std::vector<physics::Mover> movers;
      for (const Ball& b : balls_) movers.push_back({b.on_table ? &b.arc : nullptr, true});
      const NextEvent e = search_.next(movers, t_, end);
      t_ = e.t;
      if (e.kind == NextEvent::Kind::None) break;
      resolver_.resolve(e, *this);
      if (++resolved_ >= limits::kMaxEvents) {
        exhausted_ = true;
        logger("physics")->info("t={:.6f}: work budget spent ({} events); stopped", t_, resolved_);
        break;
      }
      if (!was_settled && settled()) {
        Event rest;
        rest.type = EventType::AllAtRest;
        rest.t = t_;
        events_.push_back(rest);
      }
      was_settled = settled();
    }
  }

  bool exhausted() const { return exhausted_; }

  SimResult result() const {
    SimResult r;
    r.time = t_;
    for (const Ball& b : balls_) {
      BallState s = b.state;
      if (b.on_table) {
        const Kinematics k = physics::stateAt(b.arc, t_, p_);
        s.pos = k.p;
        s.vel = k.v;
        s.w = k.w;
      } else {
        s.vel = {};
        s.w = {};
      }
      r.balls.push_back(s);
    }
    r.events = events_;
    return r;
  }

  double time() const { return t_; }
  const physics::ArcLog& arcLog() const { return log_; }

 private:
  Kinematics now(const Ball& b) const { return physics::stateAt(b.arc, t_, p_); }

  void restart(Ball& b, const Kinematics& k) {
    b.arc = physics::beginArc(t_, k, p_);
    logArc(b);
  }

  // Only balls the log knows (a trace was asked for) are logged.
  void logArc(const Ball& b) {
    const auto i = static_cast<std::size_t>(&b - balls_.data());
    if (i < log_.ids().size()) log_.record(i, b.arc);
  }

  // --- the balls as the resolver sees them ---
  std::size_t count() const override { return balls_.size(); }
  bool onTable(std::size_t i) const override { return balls_[i].on_table; }
  int id(std::size_t i) const override { return balls_[i].state.id; }
  double mass(std::size_t i) const override { return *balls_[i].state.mass; }
  Vec2 centre(std::size_t i) const override { return now(balls_[i]).p; }
  Kinematics now(std::size_t i) const override { return now(balls_[i]); }
  void restart(std::size_t i, const Kinematics& k) override { restart(balls_[i], k); }

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
  TableGeometry table_;
  physics::EventSearch search_;
  std::vector<Ball> balls_;
  std::vector<Event> events_;
  physics::Resolver resolver_;
  physics::ArcLog log_;  // filled only when the scene asks for a trace
  long resolved_ = 0;
  bool exhausted_ = false;
  double t_ = 0.0;
};

}  // namespace

SimResult simulate(const Scene& scene) {
  Run run(scene);
  if (scene.shot) run.strike(*scene.shot);
  const bool started_at_rest = run.settled();
  const auto start = std::chrono::steady_clock::now();
  if (scene.until) {
    run.run(*scene.until, false);
  } else {
    run.run(scene.step.max_time, true);
  }
  const auto stop = std::chrono::steady_clock::now();
  SimResult r = run.result();
  r.end = simEnd(scene.until.has_value(), run.exhausted(), run.settled());
  if (run.exhausted()) r.budget = std::to_string(limits::kMaxEvents) + " contacts";
  r.wall_ms = std::chrono::duration<double, std::milli>(stop - start).count();
  if (started_at_rest) {
    Event rest;
    rest.type = EventType::AllAtRest;
    r.events.push_back(rest);
  }
  if (scene.trace)
    r.trace = physics::sampleTrace(run.arcLog(), r.events, r.time, *scene.trace, scene.physics);
  return r;
}

}  // namespace nineball::reference
