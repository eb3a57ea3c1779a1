#include "physics/model/next_event.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::physics {

EventSearch::EventSearch(const TableGeometry& t, const PhysicsParams& p)
    : table(&t), shared_cushions(Cushions::sharedOf(t)), cushions(*shared_cushions), physics(p) {}

NextEvent EventSearch::ownEvent(std::size_t i, const Arc& arc, bool may_drop) const {
  NextEvent best;
  best.i = i;
  if (arc.duration < kNever) {
    best.kind = NextEvent::Kind::PhaseEnd;
    best.t = arc.end();
  }
  if (!arc.translating()) return best;
  const Clock clock = Clock::of(physics);
  const Path path = pathFrom(arc, arc.t0, physics);
  double best_s = clock.fromTime(arc.duration);
  auto take = [&](double s, NextEvent e) {
    if (s > best_s) return;
    e.i = i;
    e.t = arc.t0 + clock.toTime(s);
    best = e;
    best_s = s;
  };
  const double r = physics.ball_radius;
  if (auto hit = cushionContact(path, r, cushions, best_s)) {
    NextEvent e;
    e.kind = NextEvent::Kind::Cushion;
    e.normal = hit->normal;
    take(hit->s, e);
  }
  // A ball in the air flies over the pockets; landing in one drops it (Resolver).
  if (arc.phase == Phase::Airborne) return best;
  if (!may_drop && sensor_margin <= 0.0) return best;
  for (const Pocket& pk : table->pockets) {
    double radius = pk.drop_radius + (may_drop ? 0.0 : sensor_margin);
    // An arc that starts within the sensor's reach (a ball thrown back out of a pocket, or set
    // moving there) is "entering" it from its start, long past once the ball has left and the
    // sensor has let it go: its sensor event is where it reaches the hole itself.
    if (!may_drop && length(path.p - pk.drop_centre) < radius) radius = pk.drop_radius;
    if (auto s = circleEntry(path, pk.drop_centre, radius, best_s)) {
      NextEvent e;
      e.kind = may_drop ? NextEvent::Kind::Pocket : NextEvent::Kind::Sensor;
      e.pocket = pk.id;
      take(*s, e);
    }
  }
  return best;
}

namespace {

// The height of a ball on its arc from `from` on (the clock is the time in the air).
Height heightFrom(const Arc& arc, double from, const PhysicsParams& p) {
  if (arc.phase != Phase::Airborne) return {};
  const Kinematics k = stateAt(arc, from, p);
  return {k.z, k.vz, -p.gravity};
}

}  // namespace

std::optional<NextEvent> EventSearch::contactInAir(std::size_t i, const Arc& a, std::size_t j,
                                                   const Arc& b) const {
  const double from = std::max(a.t0, b.t0);
  const double span = std::min(a.end(), b.end()) - from;
  if (!(span >= 0.0)) return std::nullopt;  // an arc has ended: its own event comes first
  const Path pa = pathFrom(a, from, physics), pb = pathFrom(b, from, physics);
  const Height ha = heightFrom(a, from, physics), hb = heightFrom(b, from, physics);
  const auto s = ballContactInAir(pa, ha, pb, hb, 2.0 * physics.ball_radius, span);
  if (!s) return std::nullopt;
  const double dz = (hb.z0 - ha.z0) + (hb.vz - ha.vz) * *s + 0.5 * (hb.accel - ha.accel) * *s * *s;
  const Vec2 d = pb.at(*s) - pa.at(*s);
  const double apart = std::sqrt(dot(d, d) + dz * dz);
  const Vec2 dv = pb.v - pa.v + (pb.a - pa.a) * *s;
  const double dvz = (hb.vz - ha.vz) + (hb.accel - ha.accel) * *s;
  NextEvent e;
  e.kind = NextEvent::Kind::Ball;
  e.t = from + *s;
  e.i = i;
  e.j = j;
  e.closing = apart > 0.0 ? -(dot(dv, d) + dvz * dz) / apart : 0.0;
  return e;
}

std::optional<NextEvent> EventSearch::pairContact(std::size_t i, const Arc& a, std::size_t j,
                                                  const Arc& b) const {
  if (!a.translating() && !b.translating()) return std::nullopt;
  if (a.phase == Phase::Airborne || b.phase == Phase::Airborne) return contactInAir(i, a, j, b);
  // Both paths from the later start: the answer depends on the two arcs alone.
  const double from = std::max(a.t0, b.t0);
  const double span = std::min(a.end(), b.end()) - from;
  if (!(span >= 0.0)) return std::nullopt;  // an arc has ended: its own event comes first
  const Clock clock = Clock::of(physics);
  const Path pa = pathFrom(a, from, physics), pb = pathFrom(b, from, physics);
  const auto s = ballContact(pa, pb, 2.0 * physics.ball_radius, clock.fromTime(span));
  if (!s) return std::nullopt;
  const Vec2 n = normalized(pb.at(*s) - pa.at(*s));
  NextEvent e;
  e.kind = NextEvent::Kind::Ball;
  e.t = from + clock.toTime(*s);
  e.i = i;
  e.j = j;
  e.closing = -dot(pb.v - pa.v + (pb.a - pa.a) * *s, n);
  return e;
}

}  // namespace nineball::physics
