#include "physics/model/next_event.hpp"

#include <algorithm>
#include <cmath>

#include "physics/resolve/ball_ball/collide.hpp"

namespace nineball::physics {
namespace {

// Contacts closer together than this (s) are at the same instant.
constexpr double kSameInstant = 1e-12;

// The pairs that may touch within the horizon, as (owner, partner) sorted: the owner is the
// moving ball of the pair, or the lower index of two moving ones. Sort and sweep over boxes that
// hold each centre's whole reach, grown by a radius: a pair whose boxes do not overlap cannot come
// within two radii, so its contact test would answer "never". The pairs left are tested in the
// order the full double loop used, which keeps every tie-break, and the results bit for bit.
void partnersOf(const std::vector<Path>& paths, const std::vector<bool>& present,
                const std::vector<bool>& moving, double horizon, double r,
                std::vector<double>& half, std::vector<std::size_t>& order,
                std::vector<std::pair<std::size_t, std::size_t>>& pairs) {
  const std::size_t n = paths.size();
  half.assign(n, 0.0);
  order.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (!present[i]) continue;
    half[i] = (moving[i] ? reach(paths[i], horizon) : 0.0) + r + kTouchTolerance;
    order.push_back(i);
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double la = paths[a].p.x - half[a], lb = paths[b].p.x - half[b];
    return la < lb || (la == lb && a < b);
  });
  pairs.clear();  // (owner, partner)
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t a = order[k];
    const double right = paths[a].p.x + half[a];
    for (std::size_t l = k + 1; l < order.size(); ++l) {
      const std::size_t b = order[l];
      if (paths[b].p.x - half[b] > right) break;
      if (!moving[a] && !moving[b]) continue;
      if (std::abs(paths[a].p.y - paths[b].p.y) > half[a] + half[b]) continue;
      const std::size_t owner = moving[a] && moving[b] ? std::min(a, b) : moving[a] ? a : b;
      pairs.emplace_back(owner, owner == a ? b : a);
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

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
  Scratch& k = scratch_;
  std::vector<Path>& paths = k.paths;
  std::vector<std::size_t>& moving = k.moving;
  paths.assign(balls.size(), Path{});
  moving.clear();
  k.present.assign(balls.size(), false);
  k.is_moving.assign(balls.size(), false);
  std::vector<bool>& present = k.present;
  std::vector<bool>& is_moving = k.is_moving;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (!balls[i].arc) continue;
    paths[i] = pathFrom(*balls[i].arc, t, physics);
    present[i] = true;
    if (balls[i].arc->translating()) {
      moving.push_back(i);
      is_moving[i] = true;
    }
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
  partnersOf(paths, present, is_moving, horizon, r, k.half, k.order, k.pairs);
  const auto& pairs = k.pairs;
  auto next_pair = pairs.begin();
  for (std::size_t m : moving) {
    // `moving` and the pairs both run in index order: m's partners come next.
    for (; next_pair != pairs.end() && next_pair->first == m; ++next_pair) {
      const std::size_t o = next_pair->second;
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
