#pragma once

#include <vector>

#include "nineball/ball.hpp"
#include "nineball/table.hpp"

namespace nineball::snooker {

/// Where a colour potted to be re-spotted goes (WPBSA 3.7), geometry only: its own spot when
/// free; else the highest-value spot free; else as near its own spot as possible on the long
/// axis between it and the top cushion (+x); else the same towards the bottom cushion. A spot
/// is free when the ball placed there touches no other ball on the table (`balls`: every
/// ball; pocketed ones and `ball` itself are ignored) and fits on the table.
Vec2 respotPlace(int ball, const TableGeometry& table, double ball_radius,
                 const std::vector<BallState>& balls);

}  // namespace nineball::snooker
