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

std::optional<BallBallModel> BallBallModel::fromName(const std::string& name) {
  if (const auto i = placeNamed(physics::ballBallModels(), name)) return BallBallModel(*i);
  return std::nullopt;
}

BallBallModel BallBallModel::named(const std::string& name) {
  if (auto m = fromName(name)) return *m;
  throw std::invalid_argument("no ball-ball model named \"" + name + "\"");
}

std::vector<std::string> BallBallModel::names() {
  return namesOf(physics::ballBallModels());
}

bool BallBallModel::reads(const std::string& parameter) const {
  return holds(physics::ballBallModel(*this).reads, parameter);
}

const char* BallBallModel::name() const {
  return physics::ballBallModel(*this).name;
}

}  // namespace nineball
