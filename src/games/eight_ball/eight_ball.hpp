#pragma once

#include <cstdint>
#include <vector>

#include "games/game_texts.hpp"
#include "nineball/ball.hpp"
#include "nineball/games.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// The eight-ball triangle on the foot spot: 15 balls, the 8 in the centre of the third row,
/// a solid and a stripe in the two back corners, the rest (and which corner, which solid,
/// which stripe) from the seed.
std::vector<BallState> rackEightBall(const TableDef& table, double ball_radius, std::uint64_t seed,
                                     double gap = 0.0);

namespace games {

/// eight-ball: its rack, its rules' name and what else differs from game to game.
GameEntry eightBall();

}  // namespace games
}  // namespace nineball
