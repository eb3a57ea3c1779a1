#include "physics/next_event.hpp"

#include <algorithm>

namespace nineball::physics {
namespace {

// Contacts closer together than this (s) are at the same instant.
constexpr double kSameInstant = 1e-12;

}  // namespace

EventSearch::EventSearch(const TableGeometry& t, const PhysicsParams& p)
    : table(&t), shared_cushions(Cushions::sharedOf(t)), cushions(*shared_cushions), physics(p) {}

NextEvent EventSearch::next(const std::vector<Mover>& balls, double t, double until) const {
  NextEvent best;
  best.t = until;
  // Phase ends first: contacts are searched only over the stretch where every path holds.
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const Arc* arc = balls[i].arc;
    if (arc && arc->end() <= best.t) {
      best.kind = NextEvent::Kind::PhaseEnd;
      best.t = std::max(t, arc->end());
      best.i = i;
    }
  }
  const Clock clock = Clock::of(physics);
  const double horizon = clock.fromTime(best.t - t);
  std::vector<Path> paths(balls.size());
  std::vector<std::size_t> moving;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (!balls[i].arc) continue;
    paths[i] = pathFrom(*balls[i].arc, t, physics);
    if (balls[i].arc->translating()) moving.push_back(i);
  }
  double best_s = horizon;
  double best_closing = 0.0;
  auto take = [&](double s, NextEvent e) {
    if (s > best_s) return;
    e.t = t + clock.toTime(s);
    best = e;
    best_s = s;
  };
  const double r = physics.ball_radius;
  for (std::size_t m : moving) {
    for (std::size_t o = 0; o < balls.size(); ++o) {
      if (o == m || !balls[o].arc) continue;
      const bool other_moving = balls[o].arc->translating();
      if (other_moving && o < m) continue;  // the pair was seen from o
      const std::size_t i = std::min(m, o), j = std::max(m, o);
      const auto s = ballContact(paths[i], paths[j], 2.0 * r, best_s);
      if (!s) continue;
      const Vec2 n = normalized(paths[j].at(*s) - paths[i].at(*s));
      const double closing = -dot(paths[j].v - paths[i].v + (paths[j].a - paths[i].a) * *s, n);
      const bool same = best.kind == NextEvent::Kind::Ball && *s >= best_s - kSameInstant;
      if (same) {
        const bool harder =
            closing > best_closing ||
            (closing == best_closing && std::make_pair(i, j) < std::make_pair(best.i, best.j));
        if (!harder) continue;
      } else if (*s > best_s) {
        continue;
      }
      NextEvent e;
      e.kind = NextEvent::Kind::Ball;
      e.i = i;
      e.j = j;
      take(std::min(*s, best_s), e);
      best_closing = closing;
    }
    if (auto hit = cushionContact(paths[m], r, cushions, best_s)) {
      NextEvent e;
      e.kind = NextEvent::Kind::Cushion;
      e.i = m;
      e.normal = hit->normal;
      take(hit->s, e);
    }
    if (!balls[m].may_drop) continue;
    for (const Pocket& pk : table->pockets) {
      if (auto s = circleEntry(paths[m], pk.drop_centre, pk.drop_radius, best_s)) {
        NextEvent e;
        e.kind = NextEvent::Kind::Pocket;
        e.i = m;
        e.pocket = pk.id;
        take(*s, e);
      }
    }
  }
  return best;
}

}  // namespace nineball::physics
