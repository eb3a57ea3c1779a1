#pragma once

#include <string>
#include <vector>

#include "nineball/params.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

/// The tangential part of a ball-ball contact, after the normal impulse (kg m/s) of the paper's
/// collision has been applied along the unit normal n from a to b.
using BallGrip = void (*)(Kinematics& a, Kinematics& b, double mass_a, double mass_b, Vec2 n,
                          double normal_impulse, const PhysicsParams& p);

/// A ball-ball model as the resolver, the scene reader and the checks of settings know it.
struct BallBallModelDef {
  /// As scenes name it ("physics": {"ball_ball": name}) and results print it.
  const char* name = "";
  /// The grip of the contact points, or null for none (the impulse along the centres only).
  BallGrip grip = nullptr;
  /// Parameters of "physics" that only some ball-ball models read ("ball_friction"): a scene
  /// that sets one the chosen model does not read is refused, naming the models that do.
  std::vector<std::string> reads;
};

/// Every ball-ball model, in the order BallBallModel::names() gives. One line of registry.cpp
/// a model.
const std::vector<BallBallModelDef>& ballBallModels();

/// The model's definition.
const BallBallModelDef& ballBallModel(BallBallModel m);

}  // namespace nineball::physics
