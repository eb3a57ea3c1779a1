#pragma once

#include <vector>

#include "nineball/event.hpp"
#include "nineball/rules.hpp"

namespace nineball::game {

/// Reads a shot's physics events the way the rules need them: the first object ball the cue
/// ball touched, what dropped, which cushions were met and when.
rules::ShotSummary summarize(const std::vector<Event>& events);

}  // namespace nineball::game
