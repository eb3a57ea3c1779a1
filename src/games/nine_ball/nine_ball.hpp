#pragma once

#include <cstdint>
#include <vector>

#include "games/game_texts.hpp"
#include "nineball/ball.hpp"
#include "nineball/games.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// The nine-ball diamond on the foot spot: 1 at the apex, 9 in the centre, 2-8 placed from
/// the seed. `gap` is the space left between neighbouring balls (0 = frozen rack).
std::vector<BallState> rackNineBall(const TableDef& table, double ball_radius, std::uint64_t seed,
                                    double gap = 0.0);

namespace games {

/// nine-ball: its rack, its rules' name and what else differs from game to game.
GameEntry nineBall();

}  // namespace games
}  // namespace nineball
