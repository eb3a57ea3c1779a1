#pragma once

#include <cstdint>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/rules.hpp"
#include "nineball/sim.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// The standard rack of `game` (its GameDef's rack).
std::vector<BallState> rackFor(rules::Game game, const TableDef& table, double ball_radius,
                               std::uint64_t seed, double gap = 0.0);

/// The standard break: the racked table, the cue ball on the head string's centre, a shot
/// straight at the 1 ball at `speed` m/s.
Scene breakScene(std::uint64_t seed = 1, double speed = 10.0);

/// n balls on an even grid over the standard table, each rolling at 3 m/s in a seeded
/// direction: how the event search scales with the number of moving balls (the benchmarks and
/// the test that keeps an event's cost from growing with the balls on the table).
Scene movingGridScene(int n, std::uint64_t seed = 12345);

}  // namespace nineball
