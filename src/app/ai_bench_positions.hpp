#pragma once

#include <cstdint>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/params.hpp"
#include "nineball/table.hpp"

namespace nineball::app {

/// A seeded practice position: the cue ball and 3 to 5 object balls (distinct numbers 1-9)
/// placed at random on the table, none touching another or a cushion. The same seed gives
/// the same position on every machine.
std::vector<BallState> randomPosition(std::uint64_t seed, const TableDef& table,
                                      const PhysicsParams& physics);

}  // namespace nineball::app
