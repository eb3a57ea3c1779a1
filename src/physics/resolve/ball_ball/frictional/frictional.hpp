#pragma once

#include "physics/resolve/ball_ball/registry.hpp"

namespace nineball::physics {

/// Ball-ball friction (Alciatore, TP A.14): the contact points grip while they touch, which
/// throws the object ball off the line of centres and passes spin between the balls.
BallBallModelDef frictionalBallBall();

}  // namespace nineball::physics
