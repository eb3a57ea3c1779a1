#include "physics/resolve/ball_ball/frictionless/frictionless.hpp"

namespace nineball::physics {

BallBallModelDef frictionlessBallBall() {
  BallBallModelDef m;
  m.name = "frictionless";
  return m;
}

}  // namespace nineball::physics
