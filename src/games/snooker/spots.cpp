#include "games/snooker/spots.hpp"

#include "nineball/table_markings.hpp"

namespace nineball::snooker {

Vec2 colourSpot(const TableDef& table, int ball) {
  const SnookerLayout l = SnookerLayout::of(table);
  switch (ball) {
    case 16:
      return l.yellow;
    case 17:
      return l.green;
    case 18:
      return l.brown;
    case 20:
      return l.pink;
    case 21:
      return l.black;
    default:
      return l.blue;
  }
}

}  // namespace nineball::snooker
