#include "physics/engines/box2d/world.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>

#include "common/limits.hpp"
#include "common/log.hpp"
#include "nineball/cancel.hpp"
#include "physics/engines/box2d/box2d_clock.hpp"
#include "physics/engines/box2d/box2d_settings_check.hpp"
#include "physics/engines/box2d/contact_recorder.hpp"
#include "physics/engines/event_loop.hpp"
#include "physics/engines/registry.hpp"
#include "physics/model/arc_log.hpp"
#include "physics/model/event_queue.hpp"
#include "physics/model/motion.hpp"
#include "physics/model/next_event.hpp"
#include "physics/resolve/ball_ball/collide.hpp"
#include "physics/resolve/cue/cue.hpp"
#include "physics/resolve/cushion/contact.hpp"
#include "physics/resolve/cushion/simple/simple.hpp"
#include "physics/resolve/resolver.hpp"

namespace nineball {

using physics::Arc;
using physics::ContactRecorder;
using physics::FixtureKind;
using physics::fixtureTag;
using physics::Kinematics;
using physics::NextEvent;

namespace {

// Box2D clamps a body to 2 units of travel per step; stay well under it so that no speed is
// ever clipped (a piece is cut shorter instead).
constexpr double kMaxTravelUnitsPerStep = 1.5;
// Box2D resolves a bounce the world predicted in a step this short (s): the contact solver
// changes the velocity, and the ball moves by less than a float's rounding of its position.
constexpr float kBounceStep = 1e-12f;
// A ball that may not drop yet is reported this far (m) beyond a drop circle, where its body is
// moved and the pocket's sensor sees it; the sensor reaches a little further, so that Box2D's
// float test cannot miss a ball placed on the edge.
constexpr double kSensorMargin = 0.01;
constexpr double kSensorSlack = 0.001;

}  // namespace

struct World::Impl final : physics::EngineBalls, physics::LoopEngine, physics::RunState {
  struct Ball {
    int id = 0;
    double mass = 0.0;
    b2Body* body = nullptr;  // null once pocketed
    Vec2 pos;                // kept for pocketed balls
    std::optional<PocketId> pocket;
    bool off_table = false;  // left over a rail (`pocket` then names none)
    Arc arc;  // the closed form the ball follows since the last event that changed it
  };

  TableDef def;  // what the table was built from, for reset()
  TableGeometry table;
  PhysicsParams phys;
  StepParams sp;
  double k;       // Box2D units per metre
  double travel;  // m, the most a ball moves in one piece
  b2World world{b2Vec2(0.0f, 0.0f)};
  b2Body* table_body = nullptr;
  ContactRecorder recorder;
  physics::EventSearch search;
  physics::EventQueue queue{search};
  std::vector<Ball> balls;
  std::vector<Event> events;
  physics::Resolver resolver{phys, table, search.cushions, events};
  bool contacts_stale = true;  // bodies added or moved by hand: sensors not yet updated
  std::unique_ptr<physics::ArcLog> arc_log;  // every arc followed, when a trace is asked for

  Impl(const TableDef& t, const PhysicsParams& p, const StepParams& s)
      : def(t),
        table(buildTable(t, p.ball_radius)),
        phys(p),
        sp(s),
        k(s.box2d.scale),
        travel(kMaxTravelUnitsPerStep / s.box2d.scale),
        search(table, p) {
    search.sensor_margin = kSensorMargin;
    world.SetContactListener(&recorder);
    // The world predicts every contact itself: Box2D's time of impact has nothing to find,
    // and an impulse carried over from an earlier bounce must not start the next one.
    world.SetContinuousPhysics(false);
    world.SetWarmStarting(false);
    recorder.setBallRestitution(static_cast<float>(phys.ball_restitution),
                                static_cast<float>(physics::kRestingSpeed * k));
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
    fd.restitutionThreshold = static_cast<float>(physics::kRestingSpeed * k);
    fd.userData.pointer = fixtureTag(FixtureKind::Cushion, 0);
    table_body->CreateFixture(&fd);
    for (const Pocket& pk : table.pockets) {
      // A ball's body is moved to where the queue reports it entering the sensor circle, so
      // the sensor sees every ball before it can reach the drop circle.
      const double reach = pk.drop_radius + kSensorMargin + kSensorSlack - phys.ball_radius;
      b2CircleShape hole;
      hole.m_p = toB2(pk.drop_centre);
      hole.m_radius = static_cast<float>(std::max(reach, 0.001) * k);
      b2FixtureDef sd;
      sd.shape = &hole;
      sd.isSensor = true;
      sd.userData.pointer = fixtureTag(FixtureKind::Pocket, static_cast<std::size_t>(pk.id));
      table_body->CreateFixture(&sd);
    }
  }

  b2Vec2 toB2(Vec2 v) const { return {static_cast<float>(v.x * k), static_cast<float>(v.y * k)}; }
  Vec2 fromB2(const b2Vec2& v) const { return {v.x / k, v.y / k}; }

  // Where a ball is: its closed form. Its body mirrors it whenever Box2D must see it (mirror()).
  Vec2 position(const Ball& b) const {
    return b.body ? physics::stateAt(b.arc, time, phys).p : b.pos;
  }

  Kinematics now(const Ball& b) const { return physics::stateAt(b.arc, time, phys); }

  std::size_t indexOf(const Ball& b) const { return static_cast<std::size_t>(&b - balls.data()); }

  void restart(Ball& b, const Kinematics& s) {
    b.arc = physics::beginArc(time, s, phys);
    logArc(b);
    queue.changed(indexOf(b));
  }

  // Moves the ball's body to where the ball is, for a contact or sensor Box2D is about to
  // resolve; Box2D is touched only then, not as the balls travel.
  void mirror(Ball& b) {
    if (!b.body) return;
    const b2Vec2 at = toB2(position(b));
    if (b.body->GetPosition() == at) return;
    b.body->SetTransform(at, 0.0f);
    contacts_stale = true;
  }

  void mirrorAll() {
    for (Ball& b : balls) mirror(b);
  }

  void logArc(const Ball& b) {
    if (arc_log) arc_log->record(indexOf(b), b.arc);
  }

  void createBody(std::size_t index, Vec2 pos) {
    Ball& b = balls[index];
    b2BodyDef bd;
    bd.type = b2_dynamicBody;
    bd.position = toB2(pos);
    bd.fixedRotation = true;
    bd.allowSleep = false;  // Box2D's own sleeping would stop slow balls; rest is ours to call
    b.body = world.CreateBody(&bd);
    b2CircleShape shape;
    shape.m_radius = static_cast<float>(phys.ball_radius * k);
    b2FixtureDef fd;
    fd.shape = &shape;
    fd.density = 1.0f;
    fd.friction = 0.0f;
    fd.restitution = 0.0f;  // Box2D mixes by max: the cushion's e rules ball-cushion contacts
    fd.restitutionThreshold = static_cast<float>(physics::kRestingSpeed * k);
    // Pairwise: balls never meet inside Box2D; the world resolves them itself.
    fd.filter.groupIndex = sp.box2d.contacts == ContactModel::Pairwise ? -1 : 0;
    fd.userData.pointer = fixtureTag(FixtureKind::Ball, index);
    b.body->CreateFixture(&fd);
    b2MassData md;
    md.mass = static_cast<float>(b.mass);
    md.center = b2Vec2(0.0f, 0.0f);
    md.I = 0.0f;
    b.body->SetMassData(&md);
    b.pocket.reset();
    b.off_table = false;
    contacts_stale = true;
    queue.changed(index);
  }

  std::size_t indexOf(int id) const {
    for (std::size_t i = 0; i < balls.size(); ++i) {
      if (balls[i].id == id) return i;
    }
    throw std::invalid_argument("no ball with id " + std::to_string(id));
  }

  bool settled() const override {
    for (const Ball& b : balls) {
      if (b.body && b.arc.translating()) return false;
    }
    return true;
  }

  // The longest piece over which the ball stays within Box2D's travel limit (the baseline).
  double longestPiece(const Ball& b) const {
    const Kinematics s = physics::stateAt(b.arc, time, phys);
    const double v = length(s.v), a = length(b.arc.accel);
    // v h + a h^2 / 2 = travel, solved without cancellation.
    return 2.0 * travel / (v + std::sqrt(v * v + 2.0 * a * travel));
  }

  // The baseline's way: Box2D moves every travelling ball along the chord to where its closed
  // form is at the end of the piece.
  void transport(double h) {
    bool any = sp.baseline;
    for (Ball& b : balls) {
      if (!b.body) continue;
      if (b.arc.translating()) {
        const Vec2 target = physics::stateAt(b.arc, time + h, phys).p;
        b.body->SetLinearVelocity(toB2((target - fromB2(b.body->GetPosition())) / h));
        if (!b.body->IsAwake()) b.body->SetAwake(true);
        any = true;
      } else if (b.body->IsAwake()) {
        b.body->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
        if (!sp.baseline) b.body->SetAwake(false);  // a resting ball costs the solver nothing
      }
    }
    if (any) box2dStep(static_cast<float>(h), sp.box2d.position_iterations);
  }

  void box2dStep(float h, int position_iterations) {
    const physics::MutedBox2DClock muted;
    world.Step(h, sp.box2d.velocity_iterations, position_iterations);
  }

  void updateContacts() {
    // A step of no time makes Box2D find the new contacts and fire the sensors.
    box2dStep(0.0f, sp.box2d.position_iterations);
    contacts_stale = false;
  }

  // Lets Box2D's contact solver resolve what the recorder enables, every ball at its exact
  // velocity; positions are left where they are.
  void solveContactsNow() {
    for (Ball& b : balls) {
      if (!b.body) continue;
      const Vec2 v = physics::stateAt(b.arc, time, phys).v;
      b.body->SetLinearVelocity(toB2(v));
      if (v != Vec2{} && !b.body->IsAwake()) b.body->SetAwake(true);
    }
    recorder.cushion_pushes.clear();
    recorder.ball_hits.clear();
    box2dStep(kBounceStep, 0);
    recorder.bouncing = ContactRecorder::kNoBall;
    recorder.ball_contacts = false;
  }

  // --- the balls as the resolver sees them ---
  std::size_t count() const override { return balls.size(); }
  bool onTable(std::size_t i) const override { return balls[i].body != nullptr; }
  int id(std::size_t i) const override { return balls[i].id; }
  double mass(std::size_t i) const override { return balls[i].mass; }
  Vec2 centre(std::size_t i) const override { return position(balls[i]); }
  Kinematics now(std::size_t i) const override { return now(balls[i]); }
  const Arc& arc(std::size_t i) const override { return balls[i].arc; }

  void restart(std::size_t i, const Kinematics& s) override { restart(balls[i], s); }

  void nextPhase(std::size_t i) override {
    Ball& b = balls[i];
    b.arc = physics::nextArc(b.arc, phys);
    logArc(b);
    queue.changed(i);
  }

  void drop(std::size_t i, std::optional<PocketId> pocket) override {
    Ball& b = balls[i];
    b.pos = position(b);
    b.pocket = pocket.value_or(BallState::kOffTablePocket);
    b.off_table = !pocket;
    world.DestroyBody(b.body);
    b.body = nullptr;
    queue.changed(i);
    if (arc_log) arc_log->pocket(i, time, b.pos);
  }

  // How far (1 - cos) Box2D's normal at a contact may stray from the exact one and still be the
  // same face: float rounding on a straight face; on a knuckle, which the chain holds as chords,
  // as far as a chord turns, for Box2D's impulse to be applied along the arc's own normal.
  double faceAgreement(Vec2 p) const {
    double agreement = 1e-8;
    for (const physics::Cushions::Arc& arc : search.cushions.arcs) {
      const Vec2 d = p - arc.centre;
      const double gap = length(d) - arc.radius - phys.ball_radius;
      if (std::abs(gap) <= physics::kTouchTolerance && arc.covers(d)) {
        agreement = std::max(agreement, 1.0 - std::cos(arcChordAngle(arc.radius)));
      }
    }
    return agreement;
  }

  // The paper's law at a cushion, by Box2D's contact solver.
  physics::CushionRebound restitutionBounce(std::size_t i, const Kinematics& s_in, Vec2 predicted,
                                            const PhysicsParams&) override {
    Ball& b = balls[i];
    physics::CushionRebound hit;
    hit.k = s_in;
    mirror(b);
    if (contacts_stale) updateContacts();
    recorder.bouncing = i;
    solveContactsNow();
    Vec2 pushed;
    for (const auto& push : recorder.cushion_pushes) {
      if (push.ball != i) continue;
      hit.impulse += push.impulse / k;
      pushed = pushed - Vec2{push.normal.x, push.normal.y} * (push.impulse / k);
    }
    recorder.cushion_pushes.clear();
    const Vec2 v_in = s_in.v;
    // Box2D's impulse, along the exact normal: Box2D finds a face's (and a jaw point's) normal
    // from float vertices, microradians off, and a ball rattling in the jaws carries that on
    // from rebound to rebound. Its answer stands when it pushed and gave back no energy; its
    // sequential solver can push a ball wedged between two faces out faster than it came (each
    // face restores the full approach speed), and then the same law is applied by hand, one
    // face at a time.
    const double agreement = faceAgreement(s_in.p);
    const bool one_face = dot(normalized(pushed), predicted) > 1.0 - agreement;
    double along = length(pushed);
    // On a knuckle Box2D met a chord, and sized its impulse by the approach along the chord's
    // normal: the restitution it applied is carried over to the approach along the arc's.
    const double chord_approach = dot(v_in, normalized(pushed));
    if (one_face && agreement > 1e-8 && chord_approach < 0.0) {
      along *= dot(v_in, predicted) / chord_approach;
    }
    const Vec2 v_box2d =
        one_face ? v_in + predicted * (along / b.mass) : fromB2(b.body->GetLinearVelocity());
    if (hit.impulse > 0.0 && dot(v_box2d, v_box2d) <= dot(v_in, v_in)) {
      hit.k.v = v_box2d;
      hit.normal = one_face ? predicted : normalized(pushed);
      // What Box2D's float solver leaves of the approach along the normal is rounding, and
      // would be found as a new contact at once, forever.
      const double vn = dot(hit.k.v, predicted);
      if (vn < 0.0) hit.k.v -= predicted * vn;
    } else {
      if (hit.impulse <= 0.0) {
        // Box2D found no contact to push on (a touch it rounds away).
        physicsLogger().debug("t={:.6f} ball {}: Box2D saw no cushion contact", time, b.id);
      } else {
        physicsLogger().debug("t={:.6f} ball {}: Box2D's bounce gained energy; by hand", time,
                              b.id);
      }
      hit.normal = predicted;
      hit.k = physics::bounceOffCushion(hit.k, hit.normal, b.mass, phys, hit.impulse);
    }
#ifdef NINEBALL_BREAK_ENERGY
    hit.k.v = hit.k.v * 1.01;  // deliberately broken, to show that the checks catch it
#endif
    return hit;
  }

  // Box2D's simultaneous solver ("contacts": "box2d"): every touching pair at once.
  bool solvedBallContact(std::size_t i, std::size_t j) override {
    if (sp.box2d.contacts != ContactModel::Box2D) return false;
    Ball& a = balls[i];
    Ball& b = balls[j];
    mirrorAll();
    if (contacts_stale) updateContacts();
    recorder.ball_contacts = true;
    solveContactsNow();
    auto hits = recorder.ball_hits;
    for (auto& [x, y] : hits) {
      if (x > y) std::swap(x, y);
    }
    std::sort(hits.begin(), hits.end());
    hits.erase(std::unique(hits.begin(), hits.end()), hits.end());
    std::vector<bool> changed(balls.size(), false);
    for (auto [x, y] : hits) changed[x] = changed[y] = true;
    for (std::size_t m = 0; m < balls.size(); ++m) {
      if (!changed[m]) continue;
      Kinematics s = now(balls[m]);
      s.v = fromB2(balls[m].body->GetLinearVelocity());
      restart(balls[m], s);
    }
    for (auto [x, y] : hits) {
      resolver.ballEvent(time, *this, x, y, balls[x].arc.start.v, balls[y].arc.start.v);
    }
    // Box2D's sequential solver, in floats, can leave the pair it was called for still
    // closing: the same contact would be found again at the same instant, without end. It is
    // then resolved by hand, as the pairwise model does.
    const Vec2 n = normalized(position(b) - position(a));
    const double closing = dot(now(a).v - now(b).v, n);
    if (!hits.empty() && !(closing > physics::kMinClosingSpeed)) {
      // Box2D leaves positions alone: a pair pressed past the touch tolerance would be met
      // again at once for ever. It is set back to touching, as the pairwise model does.
      const Kinematics sa = now(a), sb = now(b);
      if (2.0 * phys.ball_radius - length(sb.p - sa.p) > 0.5 * physics::kTouchTolerance) {
        resolver.placeApart(*this, i, j, sa, sb);
      }
      return true;
    }
    physicsLogger().debug("t={:.6f} Box2D left balls {} and {} closing at {} m/s; by hand", time,
                          a.id, b.id, hits.empty() ? 0.0 : closing);
    return false;
  }

  // Kinetic energy, rotation included, of every ball on the table: a contact in a jam
  // settles every ball that touches it, so its own two balls are not the whole account.
  double energyOnTable() const {
    double sum = 0.0;
    for (const Ball& b : balls) {
      if (!b.body) continue;
      sum += physics::kineticEnergy(physics::stateAt(b.arc, time, phys), b.mass, phys.ball_radius);
    }
    return sum;
  }

  void resolve(const NextEvent& e) override {
#ifdef NINEBALL_CHECKED
    // Checked builds (the sanitizer build among them) stop at the first contact that gives
    // energy back, with the rounding of Box2D's single-precision velocities allowed for.
    // Box2D's own ball solver ("contacts": "box2d") is the one model known to gain energy; it
    // is kept as the measured counter-example and not checked.
    const bool contact =
        e.kind == NextEvent::Kind::Cushion ||
        (e.kind == NextEvent::Kind::Ball && sp.box2d.contacts == ContactModel::Pairwise);
    const double before = contact ? energyOnTable() : 0.0;
    resolveUnchecked(e);
    const double after = contact ? energyOnTable() : 0.0;
    if (contact && after > before * (1.0 + 1e-6) + 1e-15) {
      physicsLogger().critical("t={:.9f}: a {} contact of ball {} raised the energy {} -> {} J",
                               time, e.kind == NextEvent::Kind::Cushion ? "cushion" : "ball-ball",
                               balls[e.i].id, before, after);
      std::abort();
    }
#else
    resolveUnchecked(e);
#endif
  }

  void resolveUnchecked(const NextEvent& e) {
    if (e.kind == NextEvent::Kind::Sensor) {
      // The ball nears a pocket: its sensor must see it before it can drop.
      mirror(balls[e.i]);
      updateContacts();
      return;
    }
    resolver.resolve(e, *this);
  }

  // --- the balls as the run loop sees them ---
  std::size_t ballCount() const override {
    return balls.size();
  }

  void beginRun() override {
    if (contacts_stale) updateContacts();
  }

  // A ball over a pocket may drop only once its sensor has seen it; with the baseline, a piece
  // ends where a ball would leave Box2D's travel limit.
  double describe(std::vector<physics::Mover>& into, double end) const override {
    into.resize(balls.size());
    double limit = end;
    for (std::size_t i = 0; i < balls.size(); ++i) {
      const Ball& b = balls[i];
      into[i] = {b.body ? &b.arc : nullptr, b.body && recorder.overPocket(i)};
      if (sp.baseline && b.body && b.arc.translating())
        limit = std::min(limit, time + longestPiece(b));
    }
    return limit;
  }

  void carry(double dt) override {
    if (sp.baseline) transport(dt);
  }

  // Runs to `end` in pieces, each ending at the next event, at the travel limit or at `end`;
  // with `to_rest`, stops the moment the last ball stops travelling.
  void advance(double end, bool to_rest) {
    physics::runEvents(*this, queue, *this, end, to_rest, events);
  }

  bool runOver(double deadline) const {
    return settled() || time >= deadline || exhausted;
  }

  double boundary(long n) const {
    return physics::stepBoundary(n, sp.hz);
  }

  void step() {
    // Spent, the clock still runs (so that loops over steps end) but nothing moves.
    if (!exhausted) advance(boundary(steps + 1), false);
    time = boundary(++steps);
  }
};

World::World(const TableDef& table, const PhysicsParams& physics, const StepParams& step)
    : impl_(std::make_unique<Impl>(table, physics, step)) {}

World::~World() = default;

void World::addBall(const BallState& ball) {
  Impl& w = *impl_;
  Impl::Ball b;
  b.id = ball.id;
  b.mass = ball.mass.value_or(w.phys.ball_mass);
  b.pos = ball.pos;
  b.arc = physics::beginArc(w.time, {ball.pos, ball.vel, ball.w, ball.z, ball.vz}, w.phys);
  w.balls.push_back(b);
  w.recorder.resize(w.balls.size());
  if (w.arc_log) w.arc_log->addBall(ball.id);
  if (ball.pocket || ball.off_table) {
    w.balls.back().pocket = ball.pocket.value_or(BallState::kOffTablePocket);
    w.balls.back().off_table = ball.off_table;
    if (w.arc_log) w.arc_log->pocket(w.balls.size() - 1, w.time, ball.pos);
    return;
  }
  w.logArc(w.balls.back());
  w.createBody(w.balls.size() - 1, ball.pos);
}

bool World::strike(int ball_id, const Shot& shot) {
  Impl& w = *impl_;
  Impl::Ball& b = w.balls[w.indexOf(ball_id)];
  if (!b.body) throw std::invalid_argument("ball " + std::to_string(ball_id) + " is pocketed");
  const auto k =
      physics::strokeBall(ball_id, w.time, w.position(b), shot, b.mass, w.phys, w.events);
  if (!k) return false;
  w.restart(b, *k);
  return true;
}

void World::placeBall(int ball_id, Vec2 pos) {
  Impl& w = *impl_;
  const std::size_t i = w.indexOf(ball_id);
  Impl::Ball& b = w.balls[i];
  if (b.body) {
    b.body->SetTransform(w.toB2(pos), 0.0f);
    w.contacts_stale = true;
  } else {
    w.createBody(i, pos);
  }
  b.pos = pos;
  w.restart(b, {pos, {}, {}});
}

void World::step() {
  impl_->step();
}

void World::runFor(double seconds) {
  Impl& w = *impl_;
  const double target = w.time + seconds;
  while (w.time < target && !w.exhausted) {
    if (w.settled()) {
      // Nothing travels: only spins die away, which costs no step.
      w.advance(target, false);
      if (!w.exhausted) w.time = target;
      return;
    }
    if (w.boundary(w.steps + 1) <= target) {
      w.step();
    } else {
      w.advance(target, false);
      if (!w.exhausted) w.time = target;
    }
  }
}

bool World::stepTowardRest(double deadline) {
  Impl& w = *impl_;
  return physics::stepTowardRest(w, w.queue, w, w.sp.hz, deadline, w.events);
}

void World::runUntilRest(const std::function<bool(const std::vector<Event>&)>& stop) {
  Impl& w = *impl_;
  // The limit is the run's own: a match's world keeps its clock from shot to shot.
  const double deadline = w.time + w.sp.max_time;
  while (!w.runOver(deadline)) {
    stepTowardRest(deadline);
    if (stop && stop(w.events)) return;
  }
  physics::noteStillMoving(w, w, w.sp.max_time);
}

void World::logArcs() {
  impl_->arc_log = std::make_unique<physics::ArcLog>();
}

const physics::ArcLog* World::arcLog() const {
  return impl_->arc_log.get();
}

bool World::exhausted() const {
  return impl_->exhausted;
}

const std::string& World::budgetSpent() const {
  return impl_->budget_spent;
}

bool World::atRest() const {
  return impl_->settled();
}
double World::time() const {
  return impl_->time;
}
long World::steps() const {
  return impl_->steps;
}

std::vector<BallState> World::balls() const {
  const Impl& w = *impl_;
  std::vector<BallState> out;
  out.reserve(w.balls.size());
  for (const Impl::Ball& b : w.balls) {
    BallState s;
    s.id = b.id;
    s.pos = w.position(b);
    if (b.body) {
      const Kinematics k = physics::stateAt(b.arc, w.time, w.phys);
      s.vel = k.v;
      s.w = k.w;
      s.z = k.z;
      s.vz = k.vz;
    }
    s.mass = b.mass;
    s.pocket = b.pocket;
    s.off_table = b.off_table;
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
physics::SearchWork World::searchWork() const {
  return impl_->queue.work();
}
void World::reset() {
  // Box2D's broadphase and contact lists keep the history of what they held: only a new world
  // is the same to the bit as a new world.
  const TableDef def = impl_->def;
  const PhysicsParams physics = impl_->phys;
  const StepParams step = impl_->sp;
  impl_.reset();
  impl_ = std::make_unique<Impl>(def, physics, step);
}

namespace physics {

EngineDef box2dEngine() {
  EngineDef e;
  e.name = "box2d";
  e.make = [](const TableDef& table, const PhysicsParams& physics,
              const StepParams& step) -> std::unique_ptr<Engine> {
    return std::make_unique<World>(table, physics, step);
  };
  e.reads = {"hz", "velocity_iterations", "position_iterations", "scale", "contacts", "baseline"};
  e.check = box2dSettingsProblem;
  return e;
}

}  // namespace physics

}  // namespace nineball
