#pragma once

#include <vector>

#include "nineball/ball.hpp"

namespace nineball::play {

/// WPBSA section 2 ("snookered"): the cue ball is snookered when a direct stroke in a straight
/// line to every ball on is wholly or partly obstructed by a ball not on; when one ball on or
/// more can be hit at both extreme edges free of any ball not on, it is not. A cushion never
/// snookers (a jaw in the way is the table's, not a snooker), and a ball on never snookers
/// another. An extreme edge is hit by the cue ball's straight path that ends grazing the ball
/// on (centres 2R apart at a right angle to the path); it is free when no ball not on comes
/// within 2R of that path. A cue ball touching a ball on is not snookered (it counts as hit).
/// `cue`: the cue ball's centre; `on`: the ids of the balls on; `balls`: every ball (pocketed
/// ones and the cue ball, id 0, are ignored as obstacles).
bool snookered(Vec2 cue, const std::vector<int>& on, const std::vector<BallState>& balls,
               double ball_radius);

/// The balls resting against the cue ball at `cue` (centres within 2R and a hair).
std::vector<int> touchingBalls(Vec2 cue, const std::vector<BallState>& balls, double ball_radius);

}  // namespace nineball::play
