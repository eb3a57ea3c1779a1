#pragma once

#include <optional>
#include <vector>

#include "nineball/table.hpp"
#include "nineball/vec2.hpp"

namespace nineball {

/// What is drawn on a table's cloth, in metres: the lines, the arcs and the spots its game's
/// rules refer to. A pool table's head string and foot spot; a snooker table's baulk line, D
/// and six colour spots.
struct TableMarkings {
  struct Line {
    Vec2 a, b;
  };
  /// An arc of a circle from angle `from` to `to` (radians, counter-clockwise, x axis 0).
  struct Arc {
    Vec2 centre;
    double radius = 0.0;
    double from = 0.0, to = 0.0;
  };
  std::vector<Line> lines;
  std::vector<Arc> arcs;
  std::vector<Vec2> spots;
};

/// The spots and lines of a snooker table (WPBSA rules, section 1), scaled with the table's
/// length from the 3569 mm of a full-size one: the baulk end is -x.
struct SnookerLayout {
  double baulk_x = 0.0;   ///< the baulk line (x)
  double d_radius = 0.0;  ///< the D: a half circle centred on the baulk line's middle
  Vec2 yellow, green, brown, blue, pink, black;

  static SnookerLayout of(const TableDef& table);
  /// The colour spots from the highest value (black) to the lowest (yellow).
  std::vector<Vec2> spotsHighestFirst() const;
  /// True when p is inside the D (on or behind the baulk line, within the radius; a point on
  /// the line or the arc is in).
  bool inD(Vec2 p) const;
};

/// The markings of a table.
TableMarkings markingsOf(const TableDef& table);

}  // namespace nineball
