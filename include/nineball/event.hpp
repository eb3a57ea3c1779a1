#pragma once

#include "nineball/table.hpp"
#include "nineball/vec2.hpp"

namespace nineball {

/// Airborne: a ball leaves the cloth (a jump, a hop, a bounce that lifts it again); Land: it
/// meets the slate again; OffTable: it leaves the table over a rail.
enum class EventType { BallBall, Cushion, Pocket, AllAtRest, Miscue, Airborne, Land, OffTable };

/// Something that happened during a step, with its simulated time.
struct Event {
  EventType type = EventType::BallBall;
  double t = 0.0;  ///< s
  int a = -1;      ///< ball id (of a cushion, pocket or miscue event, the first of a pair)
  int b = -1;      ///< second ball of a ball-ball event
  Vec2 va;         ///< velocity of a just after the contact
  Vec2 vb;         ///< velocity of b just after the contact
  Vec2 at;  ///< where a's centre was, on the table's plane (airborne, land, off_table, cushion)
  PocketId pocket = PocketId::TopLeft;
};

const char* eventTypeName(EventType t);

}  // namespace nineball
