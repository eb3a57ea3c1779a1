#pragma once

#include <string>

#include "nineball/sim.hpp"

namespace nineball::window {

/// `nineball sim --png`: a traced shot drawn with the game's own painters (the table, each
/// ball's path in its colour, sliding dashed and rolling solid, every contact, cushion and
/// pocket marked, each ball faded where it started and whole where it stopped), saved as a
/// PNG whole or not at all. Needs a display (Xvfb will do); false with `why` otherwise.
bool writeShotPng(const Scene& scene, const SimResult& traced, const std::string& path,
                  std::string& why);

}  // namespace nineball::window
