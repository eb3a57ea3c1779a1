#pragma once

#include <cstdint>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/rules.hpp"
#include "nineball/sim.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// The nine-ball diamond on the foot spot: 1 at the apex, 9 in the centre, 2-8 placed from
/// the seed. `gap` is the space left between neighbouring balls (0 = frozen rack).
std::vector<BallState> rackNineBall(const TableDef& table, double ball_radius, std::uint64_t seed,
                                    double gap = 0.0);

/// The eight-ball triangle on the foot spot: 15 balls, the 8 in the centre of the third row,
/// a solid and a stripe in the two back corners, the rest (and which corner, which solid,
/// which stripe) from the seed.
std::vector<BallState> rackEightBall(const TableDef& table, double ball_radius, std::uint64_t seed,
                                     double gap = 0.0);

/// The ten-ball triangle on the foot spot: 10 balls in four rows, the 1 at the apex, the 10
/// in the centre of the third row, 2-9 from the seed.
std::vector<BallState> rackTenBall(const TableDef& table, double ball_radius, std::uint64_t seed,
                                   double gap = 0.0);

/// The standard rack of `game` (rackNineBall, rackEightBall or rackTenBall).
std::vector<BallState> rackFor(rules::Game game, const TableDef& table, double ball_radius,
                               std::uint64_t seed, double gap = 0.0);

/// The standard break: the racked table, the cue ball on the head string's centre, a shot
/// straight at the 1 ball at `speed` m/s.
Scene breakScene(std::uint64_t seed = 1, double speed = 10.0);

}  // namespace nineball
