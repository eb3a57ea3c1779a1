#include "nineball/world.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "nineball/log.hpp"
#include "physics/ball_collision.hpp"
#include "physics/cloth.hpp"
#include "physics/contact_recorder.hpp"

namespace nineball {

using physics::ContactRecorder;
using physics::FixtureKind;
using physics::fixtureTag;

namespace {

// Box2D clamps a body to 2 units of travel per step; stay well under it so that no speed is
// ever clipped (sub-steps are taken instead).
constexpr double kMaxTravelUnitsPerStep = 1.5;
// Restitution applies above this approach speed (m/s); Box2D's default of 1 unit/s would make
// slow contacts dead.
constexpr double kRestitutionThreshold = 1e-4;
// Fractions of a step closer than this count as the same instant.
constexpr double kSameInstant = 1e-9;
// A contact this soon (s) is resolved where the balls stand rather than stepped to.
constexpr double kMinPiece = 1e-9;
// A step splits at most this often at ball contacts; past it, contacts are resolved at the end
// of the step (a frozen cluster of many balls).
constexpr int kMaxPiecesPerStep = 64;

}  // namespace

struct World::Impl {
  struct Ball {
    int id = 0;
    double mass = 0.0;
    b2Body* body = nullptr;  // null once pocketed
    Vec2 pos;                // kept for pocketed balls
    std::optional<PocketId> pocket;
    // Trajectory over the current sub-step, used by the pairwise contact model.
    Vec3 w;  // angular velocity, rad/s (spin model)
    Vec2 start, move, vel;
    double from = 0.0;
    bool changed = false;
    bool active = false;  // moving, so it can meet another ball in this piece
  };

  TableGeometry table;
  PhysicsParams phys;
  StepParams sp;
  double k;  // Box2D units per metre
  b2World world{b2Vec2(0.0f, 0.0f)};
  b2Body* table_body = nullptr;
  ContactRecorder recorder;
  std::vector<Ball> balls;
  std::vector<std::size_t> active;  // scratch of firstContact
  std::vector<Event> events;
  double time = 0.0;
  long steps = 0;
  bool moving = false;
  double last_stop = 0.0;  // when the last ball came to rest

  Impl(const TableDef& t, const PhysicsParams& p, const StepParams& s)
      : table(buildTable(t, p.ball_radius)), phys(p), sp(s), k(s.scale) {
    world.SetContactListener(&recorder);
    recorder.setBallRestitution(static_cast<float>(phys.ball_restitution),
                                static_cast<float>(kRestitutionThreshold * k));
    b2BodyDef bd;
    table_body = world.CreateBody(&bd);
    std::vector<b2Vec2> loop;
    loop.reserve(table.cushion_loop.size());
    for (Vec2 v : table.cushion_loop) loop.push_back(toB2(v));
    b2ChainShape chain;
    chain.CreateLoop(loop.data(), static_cast<int32>(loop.size()));
    b2FixtureDef fd;
    fd.shape = &chain;
    fd.friction = 0.0f;
    fd.restitution = static_cast<float>(phys.cushion_restitution);
    fd.restitutionThreshold = static_cast<float>(kRestitutionThreshold * k);
    fd.userData.pointer = fixtureTag(FixtureKind::Cushion, 0);
    table_body->CreateFixture(&fd);
    for (const Pocket& pk : table.pockets) {
      b2CircleShape hole;
      hole.m_p = toB2(pk.drop_centre);
      hole.m_radius = static_cast<float>(pk.drop_radius * k);
      b2FixtureDef sd;
      sd.shape = &hole;
      sd.isSensor = true;
      sd.userData.pointer = fixtureTag(FixtureKind::Pocket, static_cast<std::size_t>(pk.id));
      table_body->CreateFixture(&sd);
    }
  }

  b2Vec2 toB2(Vec2 v) const { return {static_cast<float>(v.x * k), static_cast<float>(v.y * k)}; }
  Vec2 fromB2(const b2Vec2& v) const { return {v.x / k, v.y / k}; }

  Vec2 velocity(const Ball& b) const {
    return b.body ? fromB2(b.body->GetLinearVelocity()) : Vec2{};
  }
  Vec2 position(const Ball& b) const { return b.body ? fromB2(b.body->GetPosition()) : b.pos; }

  static bool rests(Vec2 v, Vec3 w) { return v == Vec2{} && w.x == 0.0 && w.y == 0.0; }

  void setMotion(Ball& b, Vec2 v, Vec3 w) {
    b.w = w;
    b.body->SetLinearVelocity(toB2(v));
    if (rests(v, w)) {
      b.w = {};
      if (!sp.baseline) b.body->SetAwake(false);  // a resting ball costs the solver nothing
    } else if (!b.body->IsAwake()) {
      b.body->SetAwake(true);
    }
  }
  void setVelocity(Ball& b, Vec2 v) { setMotion(b, v, b.w); }

  void createBody(std::size_t index, Vec2 pos, Vec2 vel) {
    Ball& b = balls[index];
    b2BodyDef bd;
    bd.type = b2_dynamicBody;
    bd.position = toB2(pos);
    bd.bullet = true;
    bd.fixedRotation = true;
    bd.allowSleep = false;  // Box2D's own sleeping would stop slow balls; rest is ours to call
    bd.linearDamping =
        phys.cloth == ClothModel::Damping ? static_cast<float>(phys.linear_damping) : 0.0f;
    b.body = world.CreateBody(&bd);
    b2CircleShape shape;
    shape.m_radius = static_cast<float>(phys.ball_radius * k);
    b2FixtureDef fd;
    fd.shape = &shape;
    fd.density = 1.0f;
    fd.friction = 0.0f;
    fd.restitution = 0.0f;  // Box2D mixes by max: the cushion's e rules ball-cushion contacts
    fd.restitutionThreshold = static_cast<float>(kRestitutionThreshold * k);
    // Pairwise: balls never meet inside Box2D; the world resolves them after each step.
    fd.filter.groupIndex = sp.contacts == ContactModel::Pairwise ? -1 : 0;
    fd.userData.pointer = fixtureTag(FixtureKind::Ball, index);
    b.body->CreateFixture(&fd);
    b2MassData md;
    md.mass = static_cast<float>(b.mass);
    md.center = b2Vec2(0.0f, 0.0f);
    md.I = 0.0f;
    b.body->SetMassData(&md);
    b.pocket.reset();
    setMotion(b, vel, b.w);
  }

  std::size_t indexOf(int id) const {
    for (std::size_t i = 0; i < balls.size(); ++i) {
      if (balls[i].id == id) return i;
    }
    throw std::invalid_argument("no ball with id " + std::to_string(id));
  }

  bool atRest() const {
    for (const Ball& b : balls) {
      if (b.body &&
          (b.body->GetLinearVelocity() != b2Vec2(0.0f, 0.0f) || b.w.x != 0.0 || b.w.y != 0.0)) {
        return false;
      }
    }
    return true;
  }

  double maxSpeed() const {
    double m = 0.0;
    for (const Ball& b : balls) {
      if (b.body) m = std::max(m, static_cast<double>(b.body->GetLinearVelocity().Length()));
    }
    return m / k;
  }

  // The cloth over h seconds starting at t; a ball that stops inside the interval records the
  // exact instant, so the rest event is not rounded to the step.
  void applyCloth(double t, double h) {
    if (phys.cloth == ClothModel::Damping) return;
    for (Ball& b : balls) {
      if (!b.body || (!sp.baseline && !b.body->IsAwake() && b.w == Vec3{})) continue;
      const physics::Motion m{velocity(b), b.w};
      const physics::ClothStep c =
          phys.spin() ? physics::slideAndRoll(m, h, phys) : physics::decelerate(m, h, phys);
      if (c.stopped_after) last_stop = std::max(last_stop, t + *c.stopped_after);
      setMotion(b, c.end.v, c.end.w);
    }
  }

  // Friction at the cushion nose acts on the slip of the contact point: side spin changes the
  // angle off the rail, and the rail changes the side spin (Coulomb, capped where it grips).
  void applyCushionFriction() {
    auto& pushes = recorder.cushion_pushes;
    if (phys.spin() && phys.cushion_friction > 0.0) {
      const double r = phys.ball_radius;
      for (const auto& push : pushes) {
        Ball& b = balls[push.ball];
        if (!b.body) continue;
        const Vec2 n = normalized(Vec2{push.normal.x, push.normal.y});
        const double normal_impulse = push.impulse / k;  // kg m/s
        const Vec3 arm = lift(n * r);
        const Vec2 v = velocity(b);
        const Vec2 at_contact = flat(lift(v) + cross(b.w, arm));
        const Vec2 sliding = at_contact - n * dot(at_contact, n);
        const double speed = length(sliding);
        if (speed < 1e-12) continue;
        const double grip = 2.0 / 7.0 * b.mass * speed;
        const Vec2 impulse =
            sliding * (-std::min(phys.cushion_friction * normal_impulse, grip) / speed);
        const double inertia = 0.4 * b.mass * r * r;
        setMotion(b, v + impulse / b.mass, b.w + cross(arm, lift(impulse)) * (1.0 / inertia));
      }
    }
    pushes.clear();
  }

  void stopCreepingBalls(double t) {
    if (phys.cloth != ClothModel::Damping) return;
    for (Ball& b : balls) {
      if (b.body && b.body->IsAwake() && length(velocity(b)) < phys.rest_speed) {
        setMotion(b, {}, {});
        last_stop = std::max(last_stop, t);
      }
    }
  }

  struct PairContact {
    double s;  // fraction of the piece
    std::size_t i, j;
  };

  // Each ball moves in a straight line over a piece of h seconds at its present velocity.
  // Forward: from where it is now (a prediction before Box2D moves it). Backward: ending where
  // Box2D left it, which stays exact when a cushion bounce happened earlier in the piece.
  void loadTrajectories(double h, bool backward) {
    for (Ball& b : balls) {
      if (!b.body) continue;
      b.vel = velocity(b);
      b.move = b.vel * h;
      b.start = backward ? position(b) - b.move : position(b);
      b.from = 0.0;
      b.changed = false;
    }
  }

  // The first pair to touch while closing, over the loaded trajectories.
  std::optional<PairContact> firstContact() {
    const double contact = 2.0 * phys.ball_radius;
    std::optional<PairContact> best;
    double best_closing = 0.0;
    // Only pairs with a moving ball can meet: resting balls cost nothing here.
    active.clear();
    for (std::size_t i = 0; i < balls.size(); ++i) {
      Ball& x = balls[i];
      x.active = x.body && (sp.baseline || x.vel != Vec2{});
      if (x.active) active.push_back(i);
    }
    for (std::size_t m : active) {
      for (std::size_t o = 0; o < balls.size(); ++o) {
        if (o == m || !balls[o].body || (balls[o].active && o < m)) continue;
        const std::size_t i = std::min(m, o), j = std::max(m, o);
        const Ball& a = balls[i];
        const Ball& b = balls[j];
        const double from = std::max(a.from, b.from);
        const Vec2 rel = (b.start - a.start) + (b.move - a.move) * from;
        const Vec2 rel_move = (b.move - a.move) * (1.0 - from);
        if (length(rel) - length(rel_move) > contact + physics::kTouchTolerance) continue;
        const bool closing = dot(b.vel - a.vel, normalized(rel)) < -physics::kMinClosingSpeed;
        const auto s =
            physics::contactFraction(b.start - a.start, b.move - a.move, contact, from, closing);
        if (!s) continue;
        // Contacts at the same instant (a frozen cluster) go hardest first, so the order
        // follows the physics rather than the ball numbering; the numbering only breaks ties.
        const double closing_speed = -dot(b.vel - a.vel, normalized(rel));
        const bool earlier = !best || *s < best->s - kSameInstant;
        const bool same_instant = best && !earlier && *s <= best->s + kSameInstant;
        const bool harder =
            same_instant && (closing_speed > best_closing ||
                             (closing_speed == best_closing &&
                              std::make_pair(i, j) < std::make_pair(best->i, best->j)));
        if (earlier || harder) {
          best = PairContact{*s, i, j};
          best_closing = closing_speed;
        }
      }
    }
    return best;
  }

  // Seconds until the next ball-ball contact if every ball kept its velocity, up to h.
  double nextContactIn(double h) {
    loadTrajectories(h, false);
    const auto c = firstContact();
    return c ? c->s * h : h;
  }

  // Resolves, one pair at a time in the order they happen, every contact of the piece of h
  // seconds that Box2D has just stepped (balls pass through each other inside Box2D).
  void resolvePairwise(double t0, double h) {
    loadTrajectories(h, true);
    const std::size_t cap = 1000 + 100 * balls.size();
    for (std::size_t resolved = 0;; ++resolved) {
      const auto c = firstContact();
      if (!c) break;
      if (resolved >= cap) {
        logger("physics")->warn("t={:.4f}: more than {} ball contacts in one step; stopped", t0,
                                cap);
        break;
      }
      Ball& a = balls[c->i];
      Ball& b = balls[c->j];
      const Vec2 ca = a.start + a.move * c->s, cb = b.start + b.move * c->s;
      const Vec2 normal = normalized(cb - ca);
      if (dot(b.vel - a.vel, normal) < -physics::kMinClosingSpeed) {
        const auto out =
            physics::collide(a.vel, b.vel, a.mass, b.mass, phys.ball_restitution, normal);
        a.vel = out.v1;
        b.vel = out.v2;
        Event e;
        e.type = EventType::BallBall;
        e.t = t0 + c->s * h;
        e.a = a.id;
        e.b = b.id;
        e.va = a.vel;
        e.vb = b.vel;
        events.push_back(e);
        logger("physics")->trace("t={:.5f} ball {} - ball {}", e.t, a.id, b.id);
      }
      // Both continue from the contact point with their new velocities for the rest.
      for (Ball* x : {&a, &b}) {
        const Vec2 at = x == &a ? ca : cb;
        x->move = x->vel * h;
        x->start = at - x->move * c->s;
        x->from = c->s;
        x->changed = true;
      }
    }
    for (Ball& b : balls) {
      if (!b.body || !b.changed) continue;
      b.body->SetTransform(toB2(b.start + b.move), 0.0f);
      setVelocity(b, b.vel);
    }
  }

  void recordBox2DBallHits(double t) {
    for (const auto& [i, j] : recorder.ball_hits) {
      Event e;
      e.type = EventType::BallBall;
      e.t = t;
      e.a = balls[i].id;
      e.b = balls[j].id;
      e.va = velocity(balls[i]);
      e.vb = velocity(balls[j]);
      events.push_back(e);
    }
    recorder.ball_hits.clear();
  }

  void recordCushionHits(double t) {
    auto& hits = recorder.cushion_hits;
    std::sort(hits.begin(), hits.end());
    hits.erase(std::unique(hits.begin(), hits.end()), hits.end());
    for (std::size_t i : hits) {
      if (!balls[i].body) continue;
      Event e;
      e.type = EventType::Cushion;
      e.t = t;
      e.a = balls[i].id;
      e.va = velocity(balls[i]);
      events.push_back(e);
    }
    hits.clear();
  }

  void dropPocketedBalls(double t) {
    for (std::size_t i = 0; i < balls.size(); ++i) {
      Ball& b = balls[i];
      if (!b.body || !recorder.overPocket(i)) continue;
      const Vec2 p = position(b);
      const auto pocket = table.pocketAt(p);
      if (!pocket) continue;
      b.pos = p;
      b.pocket = pocket;
      last_stop = std::max(last_stop, t);
      world.DestroyBody(b.body);  // safe: Step has returned
      b.body = nullptr;
      Event e;
      e.type = EventType::Pocket;
      e.t = t;
      e.a = b.id;
      e.pocket = *pocket;
      events.push_back(e);
      logger("physics")->debug("t={:.4f} ball {} pocketed in {}", t, b.id, pocketName(*pocket));
    }
  }

  void subStep(double t0, double h) {
    // The cloth acts half before and half after the move, so that the move uses the mean
    // speed over the step: exact for constant deceleration.
    applyCloth(t0, h / 2.0);
    const bool pairwise = sp.contacts == ContactModel::Pairwise;
    double done = 0.0;
    for (int pieces = 0; done < h; ++pieces) {
      double piece = h - done;
      // A contact earlier in the step can leave a ball faster than any was at its start.
      const double speed = maxSpeed() * k;
      if (speed * piece > kMaxTravelUnitsPerStep) piece = kMaxTravelUnitsPerStep / speed;
      if (pairwise && pieces < kMaxPiecesPerStep) {
        // Step Box2D only up to the next ball contact, so that it is resolved where the balls
        // really are, whatever the cushions did before it.
        piece = std::min(piece, nextContactIn(piece));
        if (piece < kMinPiece) {
          resolvePairwise(t0 + done, 0.0);
          continue;
        }
      }
      world.Step(static_cast<float>(piece), sp.velocity_iterations, sp.position_iterations);
      applyCushionFriction();
      recordCushionHits(t0 + done + piece);
      if (pairwise) {
        resolvePairwise(t0 + done, piece);
      } else {
        recordBox2DBallHits(t0 + done + piece);
      }
      done += piece;
    }
    applyCloth(t0 + h / 2.0, h / 2.0);
    stopCreepingBalls(t0 + h);
    dropPocketedBalls(t0 + h);
  }

  void step() {
    const double dt = sp.dt();
    double done = 0.0;
    while (done < dt) {
      const double remaining = dt - done;
      const double travel = maxSpeed() * k * remaining;
      const double pieces = std::max(1.0, std::ceil(travel / kMaxTravelUnitsPerStep));
      const double h = pieces > 1.0 ? remaining / pieces : remaining;
      subStep(time + done, h);
      done += h;
      if (pieces <= 1.0) break;
    }
    time = static_cast<double>(++steps) / sp.hz;
    const bool now_moving = !atRest();
    if (moving && !now_moving) {
      Event e;
      e.type = EventType::AllAtRest;
      e.t = std::min(time, std::max(last_stop, time - sp.dt()));
      events.push_back(e);
    }
    moving = now_moving;
  }
};

World::World(const TableDef& table, const PhysicsParams& physics, const StepParams& step)
    : impl_(std::make_unique<Impl>(table, physics, step)) {}

World::~World() = default;

void World::addBall(const BallState& ball) {
  Impl::Ball b;
  b.id = ball.id;
  b.mass = ball.mass.value_or(impl_->phys.ball_mass);
  b.pos = ball.pos;
  b.w = ball.w;
  impl_->balls.push_back(b);
  impl_->recorder.resize(impl_->balls.size());
  if (ball.pocket) {
    impl_->balls.back().pocket = ball.pocket;
    return;
  }
  impl_->createBody(impl_->balls.size() - 1, ball.pos, ball.vel);
  impl_->moving = impl_->moving || !Impl::rests(ball.vel, ball.w);
}

bool World::strike(int ball_id, const Shot& shot) {
  Impl::Ball& b = impl_->balls[impl_->indexOf(ball_id)];
  if (!b.body) throw std::invalid_argument("ball " + std::to_string(ball_id) + " is pocketed");
  const PhysicsParams& p = impl_->phys;
  if (length(shot.tip) > p.miscue_limit) {
    Event e;
    e.type = EventType::Miscue;
    e.t = impl_->time;
    e.a = ball_id;
    impl_->events.push_back(e);
    return false;
  }
  const Vec2 v = shot.velocity();
  const Vec3 w = p.spin() ? physics::strikeSpin(fromAngle(shot.heading_rad), shot.speed, shot.tip,
                                                p.ball_radius)
                          : Vec3{};
  impl_->setMotion(b, v, w);
  impl_->moving = impl_->moving || !Impl::rests(v, w);
  return true;
}

void World::placeBall(int ball_id, Vec2 pos) {
  const std::size_t i = impl_->indexOf(ball_id);
  Impl::Ball& b = impl_->balls[i];
  if (b.body) {
    b.body->SetTransform(impl_->toB2(pos), 0.0f);
    impl_->setMotion(b, {}, {});
  } else {
    b.w = {};
    impl_->createBody(i, pos, {});
  }
  b.pos = pos;
}

void World::step() {
  impl_->step();
}

void World::runFor(double seconds) {
  const long target = impl_->steps + std::lround(seconds * impl_->sp.hz);
  while (impl_->steps < target && !impl_->atRest()) impl_->step();
}

void World::runUntilRest() {
  const long limit = std::lround(impl_->sp.max_time * impl_->sp.hz);
  while (!impl_->atRest() && impl_->steps < limit) impl_->step();
  if (!impl_->atRest()) {
    logger("physics")->warn("balls still moving after {} s of simulated time; stopped",
                            impl_->sp.max_time);
  }
}

bool World::atRest() const {
  return impl_->atRest();
}
double World::time() const {
  return impl_->time;
}
long World::steps() const {
  return impl_->steps;
}

std::vector<BallState> World::balls() const {
  std::vector<BallState> out;
  out.reserve(impl_->balls.size());
  for (const Impl::Ball& b : impl_->balls) {
    BallState s;
    s.id = b.id;
    s.pos = impl_->position(b);
    s.vel = impl_->velocity(b);
    s.w = b.body ? b.w : Vec3{};
    s.mass = b.mass;
    s.pocket = b.pocket;
    out.push_back(s);
  }
  return out;
}

const std::vector<Event>& World::events() const {
  return impl_->events;
}
void World::clearEvents() {
  impl_->events.clear();
}
const TableGeometry& World::table() const {
  return impl_->table;
}
const PhysicsParams& World::physics() const {
  return impl_->phys;
}
const StepParams& World::stepParams() const {
  return impl_->sp;
}

}  // namespace nineball
