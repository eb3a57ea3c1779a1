#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "nineball/params.hpp"
#include "nineball/table.hpp"
#include "physics/model/contact_times.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

/// A ball as the event search sees it.
struct Mover {
  const Arc* arc = nullptr;  ///< null once pocketed
  bool may_drop = true;      ///< the pocket test applies (the Box2D engine asks its sensors)
};

/// The next thing that changes a ball's motion, with its exact time.
struct NextEvent {
  enum class Kind { None, PhaseEnd, Ball, Cushion, Pocket };
  Kind kind = Kind::None;
  double t = 0.0;
  std::size_t i = 0;  ///< the ball (the first of a pair)
  std::size_t j = 0;  ///< the second ball of a pair
  Vec2 normal;        ///< cushion: unit normal from the cushion to the ball
  PocketId pocket = PocketId::TopLeft;
};

/// Everything the search needs that does not change during a run.
struct EventSearch {
  const TableGeometry* table = nullptr;
  // Shared by every search on the same table: building the grid for each world of the
  // planner's thousands cost more than some of their searches.
  std::shared_ptr<const Cushions> shared_cushions;
  const Cushions& cushions;
  PhysicsParams physics;

  EventSearch(const TableGeometry& t, const PhysicsParams& p);

  /// The first event after time t and no later than `until`, over the balls' arcs: a phase
  /// ending (slide to roll, rolling to rest, spin dying), a ball contact, a cushion contact or
  /// a ball's centre entering a pocket's drop circle. Contacts at the same instant go
  /// hardest first, then by ball order, so that the order follows the physics.
  NextEvent next(const std::vector<Mover>& balls, double t, double until) const;

 private:
  // Kept from search to search, so that a search allocates nothing once the buffers have grown
  // to the number of balls (each engine owns its search; none is shared between threads).
  struct Scratch {
    std::vector<Path> paths;
    std::vector<std::size_t> moving;
    std::vector<bool> present, is_moving;
    std::vector<double> half;
    std::vector<std::size_t> order;
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
  };
  mutable Scratch scratch_;
};

}  // namespace nineball::physics
