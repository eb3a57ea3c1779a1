#include "nineball/table_markings.hpp"

#include <cmath>

namespace nineball {
namespace {

// WPBSA Official Rules, section 1 (the table): playing area 3569 mm x 1778 mm; the baulk line
// 737 mm from the face of the bottom cushion; the D a half circle of radius 292 mm centred on
// the baulk line's middle; the black spot 324 mm from the face of the top cushion; the pink
// midway between the centre spot and the face of the top cushion.
constexpr double kFullLength = 3.569;
constexpr double kBaulkFromCushion = 0.737;
constexpr double kDRadius = 0.292;
constexpr double kBlackFromCushion = 0.324;
// A point exactly on the baulk line or the D's arc counts as in the D (a cue ball placed on
// the line is in hand legally).
constexpr double kOnTheLine = 1e-9;

}  // namespace

SnookerLayout SnookerLayout::of(const TableDef& table) {
  const double s = table.length / kFullLength;
  const double hx = table.length / 2.0;
  SnookerLayout l;
  l.baulk_x = -hx + kBaulkFromCushion * s;
  l.d_radius = kDRadius * s;
  // Yellow on the D's right corner and green on its left, seen from the baulk end (-x), so
  // right is -y.
  l.yellow = {l.baulk_x, -l.d_radius};
  l.green = {l.baulk_x, l.d_radius};
  l.brown = {l.baulk_x, 0.0};
  l.blue = {0.0, 0.0};
  l.pink = {hx / 2.0, 0.0};
  l.black = {hx - kBlackFromCushion * s, 0.0};
  return l;
}

std::vector<Vec2> SnookerLayout::spotsHighestFirst() const {
  return {black, pink, blue, brown, green, yellow};
}

bool SnookerLayout::inD(Vec2 p) const {
  return p.x <= baulk_x + kOnTheLine && length(p - brown) <= d_radius + kOnTheLine;
}

TableMarkings markingsOf(const TableDef& table) {
  TableMarkings m;
  const double hy = table.width / 2.0;
  if (table.marks == TableMarks::Snooker) {
    const SnookerLayout l = SnookerLayout::of(table);
    m.lines.push_back({{l.baulk_x, hy}, {l.baulk_x, -hy}});
    m.arcs.push_back({l.brown, l.d_radius, kPi / 2.0, 3.0 * kPi / 2.0});
    m.spots = l.spotsHighestFirst();
    return m;
  }
  const double head = -table.length / 4.0;
  m.lines.push_back({{head, hy}, {head, -hy}});
  m.spots.push_back({table.length / 4.0, 0.0});
  return m;
}

}  // namespace nineball
