#include "reference/reference_engine.hpp"

#include <chrono>
#include <string>
#include <tuple>
#include <vector>

#include "nineball/limits.hpp"
#include "nineball/log.hpp"
#include "physics/arc_log.hpp"
#include "physics/ball_collision.hpp"
#include "physics/models/ball_contact.hpp"
#include "physics/models/cue.hpp"
#include "physics/models/cushion.hpp"
#include "physics/models/jam.hpp"
#include "physics/models/mathavan.hpp"
#include "physics/motion.hpp"
#include "physics/next_event.hpp"

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

class Run {
 public:
  explicit Run(const Scene& scene)
      : p_(scene.physics), table_(buildTable(scene.table, p_.ball_radius)), search_(table_, p_) {
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
      resolve(e);
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

  void pushBallEvent(const Ball& a, const Ball& b, Vec2 va, Vec2 vb) {
    Event ev;
    ev.type = EventType::BallBall;
    ev.t = t_;
    ev.a = a.state.id;
    ev.b = b.state.id;
    ev.va = va;
    ev.vb = vb;
    events_.push_back(ev);
  }

  // As World's: every ball touching i and j settled at once.
  void settleJam(std::size_t i, std::size_t j) {
    std::vector<Vec2> centres(balls_.size());
    std::vector<bool> on_table(balls_.size());
    for (std::size_t m = 0; m < balls_.size(); ++m) {
      on_table[m] = balls_[m].on_table;
      if (on_table[m]) centres[m] = now(balls_[m]).p;
    }
    physics::Jam jam;
    std::vector<std::size_t> members;
    std::tie(members, jam.pairs) = physics::jamAround(centres, on_table, i, j, p_.ball_radius);
    for (std::size_t m : members) {
      jam.balls.push_back({m, now(balls_[m]), *balls_[m].state.mass, faces(centres[m])});
    }
    physics::settleJam(jam, p_);
    physics::setJamApart(jam, table_, p_.ball_radius);
    std::vector<bool> changed(jam.balls.size());
    for (std::size_t m = 0; m < jam.balls.size(); ++m) {
      const physics::JamBall& jb = jam.balls[m];
      Ball& b = balls_[jb.index];
      changed[m] = m < 2 || jb.k.v != now(b).v || jb.k.p != centres[jb.index];
      if (changed[m]) restart(b, jb.k);
    }
    for (auto [x, y] : jam.pairs) {
      if (!changed[x] && !changed[y]) continue;
      pushBallEvent(balls_[jam.balls[x].index], balls_[jam.balls[y].index], jam.balls[x].k.v,
                    jam.balls[y].k.v);
    }
  }

  std::vector<Vec2> faces(Vec2 p) const {
    return physics::touchingNormals(p, p_.ball_radius, search_.cushions);
  }

  void resolve(const NextEvent& e) {
    Ball& a = balls_[e.i];
    switch (e.kind) {
      case NextEvent::Kind::None:
        return;
      case NextEvent::Kind::PhaseEnd:
        a.arc = physics::nextArc(a.arc, p_);
        logArc(a);
        return;
      case NextEvent::Kind::Ball: {
        Ball& b = balls_[e.j];
        if (jams_.jammed(t_, e.i, e.j)) {
          settleJam(e.i, e.j);
          return;
        }
        Kinematics ka = now(a), kb = now(b);
        physics::collideBalls(ka, kb, *a.state.mass, *b.state.mass, p_);
        physics::setApart(ka, kb, table_, p_.ball_radius);
        restart(a, ka);
        restart(b, kb);
        pushBallEvent(a, b, ka.v, kb.v);
        return;
      }
      case NextEvent::Kind::Cushion: {
        double impulse = 0.0;
        Kinematics k = now(a);
        if (physics::touchesOnly(k, e.normal, faces(k.p), p_.ball_radius)) {
          const Kinematics rested = physics::restAgainstCushion(k, e.normal, table_, p_);
          if (rested.p != k.p || rested.v != k.v || rested.w != k.w) restart(a, rested);
          return;
        }
        if (jams_.jammed(t_, e.i, physics::JamCounter::kCushion)) {
          auto normals = faces(k.p);
          normals.push_back(e.normal);
          k = physics::stopAgainst(k, normals, *a.state.mass, impulse);
        } else if (p_.cushion == CushionModel::Mathavan &&
                   -dot(k.v, e.normal) > physics::kRestingSpeed) {
          k = physics::mathavanBounce(k, e.normal, *a.state.mass, p_, impulse);
        } else {
          k = physics::bounceOffCushion(k, e.normal, *a.state.mass, p_, impulse);
        }
        // Mathavan's model holds the nose's friction already.
        if (p_.cushion == CushionModel::Simple) {
          k = physics::cushionFriction(k, e.normal, impulse, *a.state.mass, p_);
        }
        k = physics::stopPressing(k, -e.normal, p_);
        physics::setOutOfCushion(k, e.normal, table_, p_.ball_radius);
        restart(a, k);
        Event ev;
        ev.type = EventType::Cushion;
        ev.t = t_;
        ev.a = a.state.id;
        ev.va = k.v;
        events_.push_back(ev);
        return;
      }
      case NextEvent::Kind::Pocket: {
        a.state.pos = now(a).p;
        a.state.pocket = e.pocket;
        a.on_table = false;
        if (e.i < log_.ids().size()) log_.pocket(e.i, t_, a.state.pos);
        Event ev;
        ev.type = EventType::Pocket;
        ev.t = t_;
        ev.a = a.state.id;
        ev.pocket = e.pocket;
        events_.push_back(ev);
        return;
      }
    }
  }

  PhysicsParams p_;
  TableGeometry table_;
  physics::EventSearch search_;
  physics::JamCounter jams_;
  std::vector<Ball> balls_;
  std::vector<Event> events_;
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
