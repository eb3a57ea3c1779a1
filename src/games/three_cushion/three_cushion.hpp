#pragma once

#include <cstdint>
#include <vector>

#include "games/game_texts.hpp"
#include "nineball/ball.hpp"
#include "nineball/games.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// Three-cushion's opening position (UMB art. 23, the spots of art. 13): the red on the top
/// spot, the yellow (the other player's) on the bottom spot, the opener's white on the
/// starting line 182 mm to one side of it (a match table's distance, scaled to a smaller
/// table's width; odd seeds to the left, +y, even to the right).
std::vector<BallState> rackThreeCushion(const TableDef& table, double ball_radius,
                                        std::uint64_t seed, double gap = 0.0);

namespace games {

/// three-cushion: its opening position, its balls, its points and what else differs.
GameEntry threeCushion();

}  // namespace games
}  // namespace nineball
