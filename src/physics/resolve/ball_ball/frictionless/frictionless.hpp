#pragma once

#include "physics/resolve/ball_ball/registry.hpp"

namespace nineball::physics {

/// The paper's ball-ball contact: the impulse along the line of centres only, so a cut ball
/// leaves exactly along that line and no spin passes between the balls.
BallBallModelDef frictionlessBallBall();

}  // namespace nineball::physics
