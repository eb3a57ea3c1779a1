#pragma once

#include <cstdint>

#include "nineball/planner.hpp"

namespace nineball::ai {

/// The three-cushion computer: the shooter's ball's path is the search. Every heading round
/// the table (and finely across each object ball) at the level's speeds, tips and cue
/// elevations is played through the physics until the point is decided; each run of
/// neighbouring headings that scores is a candidate, the widest first. The best are struck
/// again with the level's own cueing errors and ranked by how often they still score; the
/// strongest levels also play each on to rest and look for the next point from where the balls
/// stop. With no point found it plays the shot that came closest (both balls touched, most
/// cushions). `simulations` grows by the shots simulated.
Plan planCarom(const PlanInput& in, const LevelSettings& settings, int threads, long& simulations);

}  // namespace nineball::ai
