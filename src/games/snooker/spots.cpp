#include "games/snooker/spots.hpp"

#include "nineball/table_markings.hpp"
#include "rules/snooker_balls.hpp"

namespace nineball::snooker {

Vec2 colourSpot(const TableDef& table, int ball) {
  const SnookerLayout l = SnookerLayout::of(table);
  namespace balls = rules::snooker;
  switch (ball) {
    case balls::kYellow:
      return l.yellow;
    case balls::kGreen:
      return l.green;
    case balls::kBrown:
      return l.brown;
    case balls::kPink:
      return l.pink;
    case balls::kBlack:
      return l.black;
    default:
      return l.blue;
  }
}

}  // namespace nineball::snooker
