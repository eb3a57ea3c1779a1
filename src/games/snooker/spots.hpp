#pragma once

#include "nineball/table.hpp"
#include "nineball/vec2.hpp"

// Snooker's spots by ball id (the shared contract of issue 34). The distances themselves (WPBSA
// section 1 rule 1, scaled with the table's length) live once, in SnookerLayout
// (nineball/table_markings.hpp), which the window also draws from.
namespace nineball::snooker {

/// The spot of a colour (16 yellow ... 21 black); the centre (the blue's) for another id.
Vec2 colourSpot(const TableDef& table, int ball);

}  // namespace nineball::snooker
