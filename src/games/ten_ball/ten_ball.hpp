#pragma once

#include <cstdint>
#include <vector>

#include "games/game_texts.hpp"
#include "nineball/ball.hpp"
#include "nineball/games.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// The ten-ball triangle on the foot spot: 10 balls in four rows, the 1 at the apex, the 10
/// in the centre of the third row, 2-9 from the seed.
std::vector<BallState> rackTenBall(const TableDef& table, double ball_radius, std::uint64_t seed,
                                   double gap = 0.0);

namespace games {

/// ten-ball: its rack, its rules' name and what else differs from game to game.
GameEntry tenBall();

}  // namespace games
}  // namespace nineball
