#include "games/snooker/spots.hpp"

namespace nineball::snooker {
namespace {

// The official table's playing area is 3569 mm long (WPBSA section 1 rule 1); the contract's
// distances below are for it and scale with the length.
constexpr double kOfficialLength = 3.569;
constexpr double kBaulkFromBottom = 0.737;
constexpr double kDRadius = 0.292;
constexpr double kBlackFromTop = 0.324;
// A cue ball exactly on the baulk line or the D's arc counts as in the D.
constexpr double kOnTheLine = 1e-9;

double scale(const TableDef& table) {
  return table.length / kOfficialLength;
}

}  // namespace

double baulkLineX(const TableDef& table) {
  return -table.length / 2.0 + kBaulkFromBottom * scale(table);
}

double dRadius(const TableDef& table) {
  return kDRadius * scale(table);
}

Vec2 colourSpot(const TableDef& table, int ball) {
  const double xb = baulkLineX(table);
  switch (ball) {
    case 16:  // yellow: the right corner of the D seen from the baulk end (-y)
      return {xb, -dRadius(table)};
    case 17:  // green
      return {xb, dRadius(table)};
    case 18:  // brown
      return {xb, 0.0};
    case 20:  // pink: midway between the centre and the top cushion
      return {table.length / 4.0, 0.0};
    case 21:  // black
      return {table.length / 2.0 - kBlackFromTop * scale(table), 0.0};
    default:  // blue, the centre spot
      return {0.0, 0.0};
  }
}

bool inTheD(const TableDef& table, Vec2 c) {
  const Vec2 centre{baulkLineX(table), 0.0};
  return c.x <= centre.x + kOnTheLine && length(c - centre) <= dRadius(table) + kOnTheLine;
}

}  // namespace nineball::snooker
