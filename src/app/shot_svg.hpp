#pragma once

#include <string>

#include "nineball/sim.hpp"

namespace nineball::app {

/// The sample rate `nineball sim --svg` traces at (besides every event and phase change).
constexpr double kShotSvgHz = 500.0;

/// A picture of a shot: the table to scale from the physics' own geometry (cushion loop, jaws,
/// pocket cups), each moving ball's path in its colour (sliding dashed, rolling solid; one
/// <g class="ball-path"> per moving ball), every event but "rest" marked (one element of class
/// "event" each: ball contact, cushion, pocket, miscue), a legend, and each ball numbered where
/// it started (faded) and where it ended. `result` must hold a trace of `scene`.
std::string shotSvg(const Scene& scene, const SimResult& result);

}  // namespace nineball::app
