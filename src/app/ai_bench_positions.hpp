#pragma once

#include <cstdint>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/games.hpp"
#include "nineball/params.hpp"
#include "nineball/rules.hpp"
#include "nineball/table.hpp"

namespace nineball::app {

/// A seeded practice position: the cue ball and 3 to 5 object balls placed at random on the
/// table, none touching another or a cushion: distinct numbers of the game's balls, with
/// the balls its layouts require (GameDef::required_balls). The same seed gives the same
/// position on every machine.
std::vector<BallState> randomPosition(std::uint64_t seed, const TableDef& table,
                                      const PhysicsParams& physics,
                                      rules::Game game = defaultGame().id);

}  // namespace nineball::app
