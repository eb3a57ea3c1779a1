#pragma once

#include <cstddef>
#include <memory>
#include <optional>

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
  /// Sensor: the ball's centre comes within EventSearch::sensor_margin of a pocket's drop
  /// circle, where the Box2D engine's sensor must see it (only while may_drop is false).
  enum class Kind { None, PhaseEnd, Ball, Cushion, Pocket, Sensor };
  Kind kind = Kind::None;
  double t = 0.0;
  std::size_t i = 0;  ///< the ball (the first of a pair)
  std::size_t j = 0;  ///< the second ball of a pair
  Vec2 normal;        ///< cushion: unit normal from the cushion to the ball
  PocketId pocket = PocketId::TopLeft;
  double closing = 0.0;  ///< ball contact: the speed at which the pair closes, m/s
};

/// Contacts closer together than this (s) are at the same instant.
constexpr double kSameInstant = 1e-12;

/// The predictions of one table and cloth: each is a function of the arcs it reads alone (a
/// ball's own arc, or a pair's two), so that it can be kept until one of them changes.
struct EventSearch {
  const TableGeometry* table = nullptr;
  // Shared by every search on the same table: building the grid for each world of the
  // planner's thousands cost more than some of their searches.
  std::shared_ptr<const Cushions> shared_cushions;
  const Cushions& cushions;
  PhysicsParams physics;
  /// m beyond a drop circle at which a ball that may not drop yet is reported (Kind::Sensor);
  /// 0: never.
  double sensor_margin = 0.0;

  EventSearch(const TableGeometry& t, const PhysicsParams& p);

  /// Ball i's own next event on its arc: a cushion contact, entry into a pocket's drop circle
  /// (or, with may_drop false, its sensor circle) or the arc's end, whichever comes first (a
  /// contact before an end at the same instant). None when the arc never ends.
  NextEvent ownEvent(std::size_t i, const Arc& arc, bool may_drop) const;

  /// The first contact of balls i < j on their arcs while both hold, and how fast they close.
  std::optional<NextEvent> pairContact(std::size_t i, const Arc& a, std::size_t j,
                                       const Arc& b) const;

 private:
  // pairContact when a ball of the pair is in the air: the contact in space. Kept out of line
  // and cold: inlined, it made pairContact too big to inline into the pair search of every
  // shot on the cloth, which cost a flat break 0.9 % more instructions.
  [[gnu::noinline, gnu::cold]] std::optional<NextEvent> contactInAir(std::size_t i, const Arc& a,
                                                                     std::size_t j,
                                                                     const Arc& b) const;
};

}  // namespace nineball::physics
