#pragma once

#include <cstdint>
#include <vector>

#include "games/game_texts.hpp"
#include "nineball/ball.hpp"
#include "nineball/games.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// Snooker's opening position (WPBSA 3.2, the contract of issue 34): the colours on their
/// spots and the fifteen reds in a triangle, its apex on the long axis as close behind the pink
/// (towards the black) as it goes without touching, its base parallel to the top cushion. The
/// cue ball is not placed: it is in hand in the D for the opening stroke. `gap` is the space
/// left between neighbouring reds; the seed does not matter (the reds are alike).
std::vector<BallState> rackSnooker(const TableDef& table, double ball_radius, std::uint64_t seed,
                                   double gap = 0.0);

namespace games {

/// snooker: its rack, balls, tables, the D and the re-spotting of colours.
GameEntry snooker();

}  // namespace games
}  // namespace nineball
