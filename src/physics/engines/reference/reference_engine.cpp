#include "physics/engines/reference/reference_engine.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "nineball/limits.hpp"
#include "nineball/log.hpp"
#include "physics/arc_log.hpp"
#include "physics/motion.hpp"
#include "physics/next_event.hpp"
#include "physics/resolve/cue/cue.hpp"

namespace nineball::reference {

using physics::Kinematics;
using physics::NextEvent;

ReferenceEngine::ReferenceEngine(const TableDef& table, const PhysicsParams& physics,
                                 const StepParams& step)
    : p_(physics),
      sp_(step),
      table_(buildTable(table, p_.ball_radius)),
      search_(table_, p_),
      resolver_(p_, table_, search_.cushions, events_) {}

void ReferenceEngine::addBall(const BallState& b) {
  Ball ball;
  ball.state = b;
  ball.state.mass = b.mass.value_or(p_.ball_mass);
  ball.on_table = !b.pocket;
  ball.arc = physics::beginArc(t_, {b.pos, b.vel, b.w}, p_);
  balls_.push_back(ball);
  changed();
  if (!logging_) return;
  log_.addBall(b.id);
  if (b.pocket) {
    log_.pocket(balls_.size() - 1, t_, b.pos);
  } else {
    logArc(balls_.back());
  }
}

std::size_t ReferenceEngine::indexOf(int id) const {
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    if (balls_[i].state.id == id) return i;
  }
  throw std::invalid_argument("no ball with id " + std::to_string(id));
}

bool ReferenceEngine::strike(int ball_id, const Shot& shot) {
  Ball& b = balls_[indexOf(ball_id)];
  if (!b.on_table) throw std::invalid_argument("ball " + std::to_string(ball_id) + " is pocketed");
  if (length(shot.tip) > p_.miscue_limit) {
    Event e;
    e.type = EventType::Miscue;
    e.t = t_;
    e.a = ball_id;
    events_.push_back(e);
    return false;
  }
  const physics::Strike s = physics::cueStrike(shot, *b.state.mass, p_);
  // At the arc's own start its centre is the one it was given, to the bit.
  const Vec2 at = b.arc.t0 == t_ ? b.arc.start.p : now(b).p;
  b.arc = physics::beginArc(t_, {at, s.v, s.w}, p_);
  logArc(b);
  changed();
  return true;
}

void ReferenceEngine::placeBall(int ball_id, Vec2 pos) {
  Ball& b = balls_[indexOf(ball_id)];
  b.on_table = true;
  b.state.pocket.reset();
  b.state.pos = pos;
  restart(b, {pos, {}, {}});
  changed();
}

bool ReferenceEngine::settled() const {
  for (const Ball& b : balls_) {
    if (b.on_table && b.arc.translating()) return false;
  }
  return true;
}

void ReferenceEngine::run(double end, bool to_rest, double horizon) {
  bool was_settled = settled();
  while (t_ < end && !(to_rest && settled()) && !exhausted_) {
    if (!pending_ || pending_horizon_ != horizon) {
      movers_.clear();
      for (const Ball& b : balls_) movers_.push_back({b.on_table ? &b.arc : nullptr, true});
      pending_ = search_.next(movers_, from_, horizon);
      pending_horizon_ = horizon;
    }
    const NextEvent e = *pending_;
    if (e.kind == NextEvent::Kind::None || e.t > end) {
      // Kept: the same search would find the same event from the next step.
      t_ = std::min(e.t, end);
      break;
    }
    t_ = from_ = e.t;
    pending_.reset();
    resolver_.resolve(e, *this);
    if (++resolved_ >= limits::kMaxEvents) {
      exhausted_ = true;
      budget_spent_ = std::to_string(limits::kMaxEvents) + " contacts";
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

void ReferenceEngine::changed() {
  pending_.reset();
  from_ = t_;
}

double ReferenceEngine::boundary(long n) const {
  return static_cast<double>(n) / sp_.hz;
}

bool ReferenceEngine::runOver(double deadline) const {
  return settled() || t_ >= deadline || exhausted_;
}

void ReferenceEngine::step() {
  const double end = boundary(++steps_);
  if (!exhausted_) run(end, false, end);
  t_ = end;
}

void ReferenceEngine::runFor(double seconds) {
  const double end = t_ + seconds;
  run(end, false, end);
  if (!exhausted_) t_ = end;
}

bool ReferenceEngine::stepTowardRest(double deadline) {
  if (!runOver(deadline)) run(std::min(boundary(++steps_), deadline), true, deadline);
  return runOver(deadline);
}

void ReferenceEngine::runUntilRest(const std::function<bool(const std::vector<Event>&)>& stop) {
  const double deadline = t_ + sp_.max_time;
  if (!stop) {
    // Nothing to look at between steps: one run, which takes no step (see run()).
    run(deadline, true, deadline);
  } else {
    while (!runOver(deadline)) {
      stepTowardRest(deadline);
      if (stop(events_)) return;
    }
  }
  if (!settled() && !exhausted_) {
    logger("physics")->info("balls still moving after {} s of simulated time; stopped",
                            sp_.max_time);
  }
}

void ReferenceEngine::logArcs() {
  logging_ = true;
}

const physics::ArcLog* ReferenceEngine::arcLog() const {
  return logging_ ? &log_ : nullptr;
}

std::vector<BallState> ReferenceEngine::balls() const {
  std::vector<BallState> out;
  out.reserve(balls_.size());
  for (const Ball& b : balls_) {
    BallState s = b.state;
    if (b.on_table) {
      const Kinematics k = now(b);
      s.pos = k.p;
      s.vel = k.v;
      s.w = k.w;
    } else {
      s.vel = {};
      s.w = {};
    }
    out.push_back(s);
  }
  return out;
}

Kinematics ReferenceEngine::now(const Ball& b) const {
  return physics::stateAt(b.arc, t_, p_);
}

void ReferenceEngine::restart(Ball& b, const Kinematics& k) {
  b.arc = physics::beginArc(t_, k, p_);
  logArc(b);
}

// Only balls the log knows (a trace was asked for) are logged.
void ReferenceEngine::logArc(const Ball& b) {
  const auto i = static_cast<std::size_t>(&b - balls_.data());
  if (logging_ && i < log_.ids().size()) log_.record(i, b.arc);
}

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
