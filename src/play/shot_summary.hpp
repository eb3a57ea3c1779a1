#pragma once

#include <vector>

#include "nineball/event.hpp"
#include "nineball/rules.hpp"

namespace nineball::play {

/// Reads a shot's physics events the way the rules need them: the first object ball the cue
/// ball touched, what dropped and where, which cushions were met and when. The call
/// is the shooter's, not the physics': the caller adds it.
rules::ShotSummary summarize(const std::vector<Event>& events);

}  // namespace nineball::play
