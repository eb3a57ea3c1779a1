#include "physics/model/event_queue.hpp"

#include <algorithm>
#include <cmath>

#include "physics/resolve/ball_ball/collide.hpp"

namespace nineball::physics {
namespace {

int rank(NextEvent::Kind k) {
  return static_cast<int>(k);
}

// Heap order: the earliest first; the same instant by kind, then ball, so that the order of the
// heap depends on what is in it alone.
bool later(const NextEvent& a, const NextEvent& b) {
  if (a.t != b.t) return a.t > b.t;
  if (a.kind != b.kind) return rank(a.kind) > rank(b.kind);
  if (a.i != b.i) return a.i > b.i;
  return a.j > b.j;
}

// Of two events at the same instant, the one resolved first: ball contacts before anything
// else, the hardest first; otherwise heap order.
bool first(const NextEvent& a, const NextEvent& b) {
  const bool ball_a = a.kind == NextEvent::Kind::Ball, ball_b = b.kind == NextEvent::Kind::Ball;
  if (ball_a != ball_b) return ball_a;
  if (ball_a && a.closing != b.closing) return a.closing > b.closing;
  return later(b, a);
}

}  // namespace

void EventQueue::changed(std::size_t i) {
  if (i >= state_.size()) return;  // new: next() takes it in
  BallState& b = state_[i];
  ++b.version;  // every entry of the ball is void from now on
  if (!b.dirty) {
    b.dirty = true;
    dirty_.push_back(i);
  }
}

void EventQueue::clear() {
  state_.clear();
  dirty_.clear();
  heap_.clear();
  same_.clear();
  now_ = 0.0;
  work_ = {};
}

bool EventQueue::live(const Entry& x) const {
  if (state_[x.e.i].version != x.vi) return false;
  return x.e.kind != NextEvent::Kind::Ball || state_[x.e.j].version == x.vj;
}

void EventQueue::push(const NextEvent& e) {
  Entry x;
  x.e = e;
  x.vi = state_[e.i].version;
  if (e.kind == NextEvent::Kind::Ball) x.vj = state_[e.j].version;
  heap_.push_back(x);
  std::push_heap(heap_.begin(), heap_.end(),
                 [](const Entry& a, const Entry& b) { return later(a.e, b.e); });
}

Box EventQueue::boxOf(const Arc& arc) const {
  const PhysicsParams& p = search_.physics;
  const Path path = pathFrom(arc, arc.t0, p);
  const double span = arc.translating() ? Clock::of(p).fromTime(arc.duration) : 0.0;
  return physics::boxOf(path, span).grown(p.ball_radius + kTouchTolerance);
}

void EventQueue::redoPairs(const std::vector<Mover>& balls, std::size_t i) {
  const BallState& a = state_[i];
  for (std::size_t j = 0; j < state_.size(); ++j) {
    const BallState& b = state_[j];
    if (j == i || !b.present || (b.dirty && j < i)) continue;
    if (!a.translating && !b.translating) continue;
    if (!a.box.overlaps(b.box)) continue;
    const std::size_t lo = std::min(i, j), hi = std::max(i, j);
    ++work_.pair_predictions;
    if (auto c = search_.pairContact(lo, *balls[lo].arc, hi, *balls[hi].arc)) push(*c);
  }
}

void EventQueue::redo(const std::vector<Mover>& balls) {
  if (dirty_.empty()) return;
  std::sort(dirty_.begin(), dirty_.end());
  for (std::size_t i : dirty_) {
    BallState& b = state_[i];
    const Mover& m = balls[i];
    b.present = m.arc != nullptr;
    b.may_drop = m.may_drop;
    if (!b.present) continue;
    b.translating = m.arc->translating();
    b.box = boxOf(*m.arc);
    ++work_.ball_predictions;
    const NextEvent own = search_.ownEvent(i, *m.arc, m.may_drop);
    if (own.kind != NextEvent::Kind::None) push(own);
  }
  for (std::size_t i : dirty_) {
    if (state_[i].present) redoPairs(balls, i);
  }
  for (std::size_t i : dirty_) state_[i].dirty = false;
  dirty_.clear();
  compact();
}

// Void entries are dropped as they surface; a long run of changes to balls whose entries lie
// far ahead would let them pile up, so the heap is swept once they outnumber the live ones.
void EventQueue::compact() {
  const std::size_t n = state_.size();
  if (heap_.size() <= 256 + 4 * n * n) return;
  heap_.erase(std::remove_if(heap_.begin(), heap_.end(), [&](const Entry& x) { return !live(x); }),
              heap_.end());
  std::make_heap(heap_.begin(), heap_.end(),
                 [](const Entry& a, const Entry& b) { return later(a.e, b.e); });
}

NextEvent EventQueue::next(const std::vector<Mover>& balls, double until) {
  const auto order = [](const Entry& a, const Entry& b) { return later(a.e, b.e); };
  while (state_.size() < balls.size()) {
    dirty_.push_back(state_.size());
    state_.emplace_back();
  }
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const BallState& b = state_[i];
    const bool present = balls[i].arc != nullptr;
    if (!b.dirty && (present != b.present || (present && balls[i].may_drop != b.may_drop)))
      changed(i);
  }
  redo(balls);
  auto pop = [&] {
    std::pop_heap(heap_.begin(), heap_.end(), order);
    Entry x = heap_.back();
    heap_.pop_back();
    return x;
  };
  while (!heap_.empty() && !live(heap_.front())) pop();
  if (heap_.empty() || heap_.front().e.t > until) {
    NextEvent none;
    none.t = until;
    return none;
  }
  same_.clear();
  same_.push_back(pop());
  const double instant = same_.front().e.t + kSameInstant;
  while (!heap_.empty()) {
    if (!live(heap_.front())) {
      pop();
    } else if (heap_.front().e.t <= instant) {
      same_.push_back(pop());
    } else {
      break;
    }
  }
  std::size_t chosen = 0;
  for (std::size_t k = 1; k < same_.size(); ++k) {
    if (first(same_[k].e, same_[chosen].e)) chosen = k;
  }
  for (std::size_t k = 0; k < same_.size(); ++k) {
    if (k == chosen) continue;
    heap_.push_back(same_[k]);
    std::push_heap(heap_.begin(), heap_.end(), order);
  }
  NextEvent e = same_[chosen].e;
  // Handed out, the event's predictions are spent: its balls are worked out again next time,
  // whatever the engine does with it.
  changed(e.i);
  if (e.kind == NextEvent::Kind::Ball) changed(e.j);
  e.t = std::max(e.t, now_);
  now_ = e.t;
  ++work_.events;
  return e;
}

}  // namespace nineball::physics
