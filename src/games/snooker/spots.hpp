#pragma once

#include "nineball/table.hpp"
#include "nineball/vec2.hpp"

// The markings of a snooker table (the shared contract of issue 34), scaled to any table's
// length: s = length / 3.569 m, the official table's s being 1. WPBSA section 1 rule 1: the
// baulk line 737 mm (29 in) from the face of the bottom cushion, the D a semicircle of 292 mm
// (11.5 in) radius on it, the black spot 324 mm (12.75 in) from the top cushion, the pink
// midway between the centre and the top cushion.
namespace nineball::snooker {

/// x of the baulk line (the baulk end is at -x).
double baulkLineX(const TableDef& table);
/// Radius of the D, centred on the baulk line at y = 0, on the baulk side.
double dRadius(const TableDef& table);
/// The spot of a colour (16 yellow ... 21 black); the centre for another id.
Vec2 colourSpot(const TableDef& table, int ball);
/// A cue ball centred at `c` is in the D (on its line or arc included).
bool inTheD(const TableDef& table, Vec2 c);

}  // namespace nineball::snooker
