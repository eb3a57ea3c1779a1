#pragma once

#include <cstdint>

#include "app/game_options.hpp"

namespace nineball::window {

/// A seed never drawn before (the system's entropy and the clock): a new rack, and new cueing
/// errors for the computer, for each game a person starts without --seed.
std::uint64_t freshSeed();

/// True when the game's racks come from fresh seeds: a person plays (no --screenshot, --frames
/// or script, whose pictures and turns must come out the same run after run) and gave no
/// --seed. A joiner plays the host's racks.
bool drawsFreshSeeds(const app::GameOptions& options);

}  // namespace nineball::window
