#include "physics/resolve/ball_ball/registry.hpp"

#include <stdexcept>

#include "common/named.hpp"
#include "physics/resolve/ball_ball/frictional/frictional.hpp"
#include "physics/resolve/ball_ball/frictionless/frictionless.hpp"

namespace nineball {
namespace physics {

const std::vector<BallBallModelDef>& ballBallModels() {
  static const std::vector<BallBallModelDef> models{
      frictionlessBallBall(),
      frictionalBallBall(),
  };
  return models;
}

const BallBallModelDef& ballBallModel(BallBallModel m) {
  return ballBallModels()[m.index()];
}

}  // namespace physics

std::size_t BallBallModel::registrySize() {
  return physics::ballBallModels().size();
}

const char* BallBallModel::registryName(std::size_t index) {
  return physics::ballBallModels()[index].name;
}

bool BallBallModel::reads(const std::string& parameter) const {
  return holds(physics::ballBallModel(*this).reads, parameter);
}

}  // namespace nineball
