#pragma once

#include <vector>

#include "nineball/ball.hpp"
#include "nineball/event.hpp"
#include "nineball/rules.hpp"

namespace nineball::play {

/// Reads a shot's physics events the way the rules need them: the first object ball the cue
/// ball (`cue`: the ball struck) touched, every ball it touched and the cushions it had met
/// before each, what dropped and where, which cushions were met and when. The call is the
/// shooter's, not the physics': the caller adds it.
rules::ShotSummary summarize(const std::vector<Event>& events, int cue = kCueBall);

}  // namespace nineball::play
