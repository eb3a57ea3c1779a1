#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "physics/model/next_event.hpp"
#include "physics/model/search_work.hpp"

namespace nineball::physics {

/// Every ball's own next event and every pair's next contact, each worked out once and kept
/// until one of its balls changes motion; the next event comes off a heap. An engine tells the
/// queue which balls changed (changed()); the next call to next() redoes their predictions
/// alone, so an event costs in proportion to the balls it touched, not to the balls on the
/// table. Entries made void by a change stay in the heap and are dropped when they surface.
class EventQueue {
 public:
  explicit EventQueue(const EventSearch& search) : search_(search) {}

  /// Ball i's arc changed, or it was added or pocketed: its predictions are void.
  void changed(std::size_t i);

  /// The first event no later than `until` (Kind::None at `until` when there is none), never
  /// before the last event handed out. Contacts within kSameInstant of the first go hardest
  /// first, then by ball order, so that the order follows the physics. A Mover's may_drop is
  /// compared with the last call's: a change counts as a change of the ball.
  NextEvent next(const std::vector<Mover>& balls, double until);

  /// As new: no balls, no predictions, nothing counted.
  void clear();

  const SearchWork& work() const { return work_; }

 private:
  struct Entry {
    NextEvent e;
    std::uint32_t vi = 0, vj = 0;  // the balls' versions when it was worked out
  };
  struct BallState {
    std::uint32_t version = 0;
    bool dirty = true;
    bool present = false;
    bool may_drop = true;
    bool translating = false;
    Box box{};
  };

  bool live(const Entry& e) const;
  void push(const NextEvent& e);
  void redo(const std::vector<Mover>& balls);
  void redoPairs(const std::vector<Mover>& balls, std::size_t i);
  Box boxOf(const Arc& arc) const;
  void compact();

  const EventSearch& search_;
  std::vector<BallState> state_;
  std::vector<std::size_t> dirty_;
  std::vector<Entry> heap_;
  std::vector<Entry> same_;  // entries at the first event's instant, kept between calls
  double now_ = 0.0;
  SearchWork work_;
};

}  // namespace nineball::physics
