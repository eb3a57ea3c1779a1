#pragma once

#include <string>

#include "nineball/match.hpp"
#include "nineball/rules.hpp"
#include "window/turn_message.hpp"

namespace nineball::window {

/// What a snooker turn gave, as a referee says it: the balls potted and their points with the
/// break so far, or the foul, its penalty and whether it was a miss; the free ball and the
/// choice the fouled player now has; the decision taken; the re-spotted black; the frame's end
/// and its score. `rack` is the rack after the turn.
TurnMessage describeSnookerTurn(const TurnRecord& record, const rules::Rack& rack,
                                const std::string& shooter, const std::string& opponent);

}  // namespace nineball::window
