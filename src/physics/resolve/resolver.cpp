#include "physics/resolve/resolver.hpp"

#include <algorithm>
#include <tuple>

#include "common/log.hpp"
#include "physics/model/pocket_capture.hpp"
#include "physics/resolve/ball_ball/ball_contact.hpp"
#include "physics/resolve/ball_ball/collide.hpp"
#include "physics/resolve/ball_ball/collide_in_air.hpp"
#include "physics/resolve/cushion/contact.hpp"
#include "physics/resolve/cushion/registry.hpp"
#include "physics/resolve/cushion/simple/simple.hpp"
#include "physics/resolve/jam/jam.hpp"
#include "physics/resolve/simultaneous/simultaneous.hpp"

namespace nineball::physics {

bool EngineBalls::solvedBallContact(std::size_t, std::size_t) {
  return false;
}

CushionRebound EngineBalls::restitutionBounce(std::size_t i, const Kinematics& k, Vec2 predicted,
                                              const PhysicsParams& p) {
  CushionRebound hit;
  hit.normal = predicted;
  hit.k = bounceOffCushion(k, predicted, mass(i), p, hit.impulse);
  return hit;
}

Resolver::Resolver(const PhysicsParams& p, const TableGeometry& table, const Cushions& cushions,
                   std::vector<Event>& events)
    : p_(p), table_(table), cushions_(cushions), events_(events) {}

void Resolver::resolve(const NextEvent& e, EngineBalls& balls) {
  switch (e.kind) {
    case NextEvent::Kind::None:
    case NextEvent::Kind::Sensor:  // the engine's own business
      return;
    case NextEvent::Kind::PhaseEnd:
      phaseEnd(e.t, balls, e.i);
      return;
    case NextEvent::Kind::Ball:
      ballContact(e.t, balls, e.i, e.j);
      return;
    case NextEvent::Kind::Cushion:
      cushionContact(e.t, balls, e.i, e.normal);
      return;
    case NextEvent::Kind::Pocket:
      pocket(e.t, balls, e.i, e.pocket);
      return;
  }
}

void Resolver::ballEvent(double t, const EngineBalls& balls, std::size_t i, std::size_t j, Vec2 va,
                         Vec2 vb) {
  Event e;
  e.type = EventType::BallBall;
  e.t = t;
  e.a = balls.id(i);
  e.b = balls.id(j);
  e.va = va;
  e.vb = vb;
  events_.push_back(e);
  physicsLogger().trace("t={:.6f} ball {} - ball {}", t, e.a, e.b);
}

void Resolver::placeApart(EngineBalls& balls, std::size_t i, std::size_t j, Kinematics sa,
                          Kinematics sb) const {
  setApart(sa, sb, table_, p_.ball_radius);
  balls.restart(i, sa);
  balls.restart(j, sb);
}

void Resolver::ballContact(double t, EngineBalls& balls, std::size_t i, std::size_t j) {
  if (balls.arc(i).phase == Phase::Airborne || balls.arc(j).phase == Phase::Airborne) {
    contactInAir(t, balls, i, j);
    return;
  }
  if (balls.solvedBallContact(i, j)) return;
  if (jams_.jammed(t, i, j)) {
    settleJam(t, balls, i, j);
    return;
  }
  if (p_.frozen == ContactOrder::Simultaneous && frozenContact(t, balls, i, j)) return;
  Kinematics sa = balls.now(i), sb = balls.now(j);
  collideBalls(sa, sb, balls.mass(i), balls.mass(j), p_);
  placeApart(balls, i, j, sa, sb);
  ballEvent(t, balls, i, j, sa.v, sb.v);
}

// A ball struck while it touches a cushion the strike presses it into ("frozen": "simultaneous"):
// both normal impulses solved together (strikeFrozen). Only the plain case, one ball on one
// face; a ball on two faces, or both balls on cushions, are left to the contacts one by one.
// False when it is not that case.
bool Resolver::frozenContact(double t, EngineBalls& balls, std::size_t i, std::size_t j) {
  const Vec2 n = normalized(balls.centre(j) - balls.centre(i));
  std::size_t held = 0, other = 0, found = 0;
  Vec2 face;
  const double reach = p_.ball_radius + p_.frozen_tolerance;
  for (auto [x, y, push] : {std::tuple{i, j, n * -1.0}, std::tuple{j, i, n}}) {
    for (Vec2 f : touchingNormals(balls.centre(x), reach, cushions_)) {
      if (dot(push, f) >= -1e-9) continue;  // the strike does not press it into this face
      ++found;
      held = x;
      other = y;
      face = f;
    }
  }
  if (found != 1) return false;
  Kinematics sh = balls.now(held);
  if (dot(sh.v, face) > kMinClosingSpeed) return false;  // already leaving the cushion
  // A ball within frozen_tolerance of the cushion is taken as frozen to it: set against it.
  const double gap = p_.frozen_tolerance - cushionSink(table_, sh.p, reach);
  if (gap > kTouchTolerance) sh.p -= face * gap;
  const FrozenStrike hit =
      strikeFrozen(balls.now(other), sh, balls.mass(other), balls.mass(held), face, p_);
  const Kinematics si = held == i ? hit.b : hit.a, sj = held == i ? hit.a : hit.b;
  placeApart(balls, i, j, si, sj);
  ballEvent(t, balls, i, j, si.v, sj.v);
  if (hit.cushion_impulse > 0.0) cushionEvent(t, balls, held, hit.b.v, hit.b.p);
  return true;
}

// A ball that meets a second cushion within cushion_contact_time of this one ("corner":
// "simultaneous"): both normals resolved together (intoCorner). False when no second cushion
// is that near.
bool Resolver::cornerContact(double t, EngineBalls& balls, std::size_t i, const Kinematics& k,
                             Vec2 predicted) {
  const auto second = secondFace(k, predicted, p_.ball_radius, cushions_, p_.cushion_contact_time);
  if (!second) return false;
  const CornerBounce hit = intoCorner(k, predicted, *second, balls.mass(i), p_);
  Kinematics out = hit.k;
  setOutOfCushion(out, predicted, table_, p_.ball_radius);
  setOutOfCushion(out, *second, table_, p_.ball_radius);
  balls.restart(i, out);
  for (double impulse : hit.impulse) {
    if (impulse > 0.0) cushionEvent(t, balls, i, out.v, out.p);
  }
  return true;
}

// A contact of i and j in a jam: every ball touching them settled at once (see settleJam).
void Resolver::settleJam(double t, EngineBalls& balls, std::size_t i, std::size_t j) {
  const std::size_t n = balls.count();
  std::vector<Vec2> centres(n);
  std::vector<bool> on_table(n);
  for (std::size_t m = 0; m < n; ++m) {
    on_table[m] = balls.onTable(m);
    if (on_table[m]) centres[m] = balls.centre(m);
  }
  Jam jam;
  std::vector<std::size_t> members;
  std::tie(members, jam.pairs) = jamAround(centres, on_table, i, j, p_.ball_radius);
  for (std::size_t m : members) {
    jam.balls.push_back({m, balls.now(m), balls.mass(m), faces(centres[m])});
  }
  physics::settleJam(jam, p_);
  setJamApart(jam, table_, p_.ball_radius);
  std::vector<bool> changed(jam.balls.size());
  for (std::size_t m = 0; m < jam.balls.size(); ++m) {
    const JamBall& jb = jam.balls[m];
    changed[m] = m < 2 || jb.k.v != balls.now(jb.index).v || jb.k.p != centres[jb.index];
    if (changed[m]) balls.restart(jb.index, jb.k);
  }
  for (auto [x, y] : jam.pairs) {
    if (!changed[x] && !changed[y]) continue;
    ballEvent(t, balls, jam.balls[x].index, jam.balls[y].index, jam.balls[x].k.v, jam.balls[y].k.v);
  }
}

void Resolver::cushionContact(double t, EngineBalls& balls, std::size_t i, Vec2 predicted) {
  Kinematics k = balls.now(i);
  // In the air with its bottom over the cushion's nose: it flies over the rail, off the table.
  if (balls.arc(i).phase == Phase::Airborne && k.z >= p_.cushion_height) {
    offTable(t, balls, i);
    return;
  }
  const double mass = balls.mass(i);
  if (touchesOnly(k, predicted, faces(k.p), p_.ball_radius)) {
    const Kinematics rested = restAgainstCushion(k, predicted, table_, p_);
    if (rested.p != k.p || rested.v != k.v || rested.w != k.w) balls.restart(i, rested);
    return;
  }
  if (jams_.jammed(t, i, JamCounter::kCushion)) {
    // In a jam: no bounce, and every face it touches at once (see JamCounter).
    double impulse = 0.0;
    auto normals = faces(k.p);
    normals.push_back(predicted);
    k = stopAgainst(k, normals, mass, impulse);
    settleOnCushion(t, balls, i, k, predicted, predicted, impulse);
    return;
  }
  if (p_.corner == ContactOrder::Simultaneous && -dot(k.v, predicted) > kRestingSpeed &&
      cornerContact(t, balls, i, k, predicted)) {
    return;
  }
  const CushionModelDef& model = cushionModel(p_.cushion);
  if (model.bounce && -dot(k.v, predicted) > kRestingSpeed) {
    double impulse = 0.0;
    k = model.bounce(k, predicted, mass, p_, impulse);
    settleOnCushion(t, balls, i, k, predicted, predicted, impulse);
    return;
  }
  const CushionRebound hit = balls.restitutionBounce(i, k, predicted, p_);
  settleOnCushion(t, balls, i, hit.k, hit.normal, predicted, hit.impulse);
}

// After the bounce itself: the rail's friction, the pressing spin taken away, the ball set
// out of the cushion, and the event.
void Resolver::settleOnCushion(double t, EngineBalls& balls, std::size_t i, Kinematics k,
                               Vec2 normal, Vec2 predicted, double impulse) {
  // A model with a rebound of its own holds the nose's friction already.
  if (!cushionModel(p_.cushion).bounce) {
    k = cushionFriction(k, normal, impulse, balls.mass(i), p_);
  }
  k = stopPressing(k, -normal, p_);
  setOutOfCushion(k, predicted, table_, p_.ball_radius);
  balls.restart(i, k);
  cushionEvent(t, balls, i, k.v, k.p);
}

// A ball in the air meets the slate (Land, and Airborne again when it bounces up); one that
// comes down within a pocket's drop circle falls in.
void Resolver::phaseEnd(double t, EngineBalls& balls, std::size_t i) {
  const bool flying = balls.arc(i).phase == Phase::Airborne;
  balls.nextPhase(i);
  if (!flying) return;
  const Arc& after = balls.arc(i);
  ballEventOf(EventType::Land, t, balls, i, after.start.v, after.start.p);
  if (const auto hole = table_.pocketAt(after.start.p)) {
    pocket(t, balls, i, *hole);
    return;
  }
  // Down beyond the cushions (over a pocket's mouth and past it): off the table.
  if (!table_.insideLoop(after.start.p)) {
    offTable(t, balls, i);
    return;
  }
  if (after.phase == Phase::Airborne) {
    ballEventOf(EventType::Airborne, t, balls, i, after.start.v, after.start.p);
  }
}

// The ball leaves the table over a rail (WPA "jumped ball"): it is taken off where it is.
void Resolver::offTable(double t, EngineBalls& balls, std::size_t i) {
  const Kinematics k = balls.now(i);
  balls.drop(i, std::nullopt);
  ballEventOf(EventType::OffTable, t, balls, i, k.v, k.p);
}

// Two balls meeting with one at least in the air: in space, frictionless (collideInAir).
void Resolver::contactInAir(double t, EngineBalls& balls, std::size_t i, std::size_t j) {
  const bool flew[2] = {balls.arc(i).phase == Phase::Airborne,
                        balls.arc(j).phase == Phase::Airborne};
  Kinematics sa = balls.now(i), sb = balls.now(j);
  collideInAir(sa, sb, balls.mass(i), balls.mass(j), p_);
  balls.restart(i, sa);
  balls.restart(j, sb);
  ballEvent(t, balls, i, j, sa.v, sb.v);
  for (const auto& [m, was] : {std::pair{i, flew[0]}, std::pair{j, flew[1]}}) {
    const Arc& now = balls.arc(m);
    if (!was && now.phase == Phase::Airborne) {
      ballEventOf(EventType::Airborne, t, balls, m, now.start.v, now.start.p);
    }
  }
}

void Resolver::ballEventOf(EventType type, double t, const EngineBalls& balls, std::size_t i,
                           Vec2 v, Vec2 at) {
  Event e;
  e.type = type;
  e.t = t;
  e.a = balls.id(i);
  e.va = v;
  e.at = at;
  events_.push_back(e);
  physicsLogger().trace("t={:.6f} ball {} {}", t, e.a, eventTypeName(type));
}

void Resolver::cushionEvent(double t, const EngineBalls& balls, std::size_t i, Vec2 v, Vec2 at) {
  Event e;
  e.type = EventType::Cushion;
  e.t = t;
  e.a = balls.id(i);
  e.va = v;
  e.at = at;
  events_.push_back(e);
  physicsLogger().trace("t={:.6f} ball {} - cushion", t, e.a);
}

// The ball's centre is over the fall edge. With the "fall" model it may yet be thrown back out
// (fallIntoPocket): the whole flight is worked out now, for nothing on the table can reach a
// ball below the slate, and collapsed into this instant (docs/physics.md, "Pockets"): the
// ball is set on the fall edge where it would come back, moving as it would, its contacts with
// the back and facings recorded as cushion contacts now.
void Resolver::pocket(double t, EngineBalls& balls, std::size_t i, PocketId pocket) {
  if (p_.pocket == PocketModel::Fall && thrownBack(t, balls, i, pocket)) return;
  balls.drop(i, pocket);
  Event e;
  e.type = EventType::Pocket;
  e.t = t;
  e.a = balls.id(i);
  e.pocket = pocket;
  events_.push_back(e);
  physicsLogger().debug("t={:.6f} ball {} pocketed in {}", t, e.a, pocketName(pocket));
}

// True when the ball comes back out (and is set back on the table); false when it is caught.
bool Resolver::thrownBack(double t, EngineBalls& balls, std::size_t i, PocketId pocket) {
  const auto hole = std::find_if(table_.pockets.begin(), table_.pockets.end(),
                                 [&](const Pocket& candidate) { return candidate.id == pocket; });
  if (hole == table_.pockets.end()) return false;
  const PocketFall fall = fallIntoPocket(balls.now(i), *hole, cushions_, p_);
  if (fall.caught) return false;
  // A ball on the table where it would climb out blocks the way: it falls back in.
  for (std::size_t m = 0; m < balls.count(); ++m) {
    if (m == i || !balls.onTable(m)) continue;
    if (length(balls.centre(m) - fall.out.p) < 2.0 * p_.ball_radius) return false;
  }
  for (Vec2 v : fall.wall_contacts) cushionEvent(t, balls, i, v, fall.out.p);
  balls.restart(i, fall.out);
  physicsLogger().debug("t={:.6f} ball {} thrown back out of {} ({} walls, {:.4f} s in the air)", t,
                        balls.id(i), pocketName(pocket), fall.wall_contacts.size(), fall.t_out);
  return true;
}

std::vector<Vec2> Resolver::faces(Vec2 p) const {
  return touchingNormals(p, p_.ball_radius, cushions_);
}

}  // namespace nineball::physics
