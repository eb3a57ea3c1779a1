#pragma once

#include <vector>

#include "nineball/ball.hpp"
#include "nineball/event.hpp"

namespace nineball::play {

/// WPBSA section 2 ("jump shot"): the object balls the cue ball passed over before it first
/// touched one, landing on their far side. A flight is the straight line on the table's plane
/// from an `airborne` event's place to the next `land` (or `off_table`), bent where it meets a
/// cushion; it passes over a ball
/// whose centre lies within 2R of it, between its ends. A flight in which the cue ball touches
/// a ball ends the search: that contact is its first (the rule's exceptions: a ball first hit
/// and then jumped, or hit in the air without landing beyond it, is no jump shot). `before`:
/// the balls where they lay before the stroke (they lie there still until the cue ball's first
/// contact).
std::vector<int> ballsJumpedOver(const std::vector<Event>& events,
                                 const std::vector<BallState>& before, double ball_radius,
                                 int cue = kCueBall);

}  // namespace nineball::play
