#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nineball/params.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

/// A ball's rebound from a cushion: its velocity and spin just after (the centre where it
/// was), and the normal impulse the cushion gave (kg m/s) in `impulse`. `inward` is the
/// cushion's normal, into the table.
using CushionBounce = Kinematics (*)(Kinematics k, Vec2 inward, double mass, const PhysicsParams& p,
                                     double& impulse);

/// A cushion model as the resolver, the scene reader and the checks of settings know it.
struct CushionModelDef {
  /// As scenes name it ("physics": {"cushion": name}) and results print it.
  const char* name = "";
  /// The rebound. Null for the paper's restitution law, which the resolver follows with the
  /// nose's friction (cushionFriction), and which the Box2D engine lets Box2D's solver apply.
  /// A model with a rebound of its own holds the nose's friction already.
  CushionBounce bounce = nullptr;
  /// Parameters that only some cushion models read (today "cushion_height"): a scene that
  /// sets one the chosen model does not read is refused, naming the models that do.
  std::vector<std::string> reads;
  /// Parameters every other model reads that this one does not (a restitution it takes from
  /// elsewhere): a scene that sets one with this model is refused.
  std::vector<std::string> ignores;
  /// Why settings cannot run with this model (a message naming the field), or nothing.
  std::optional<std::string> (*check)(const PhysicsParams& p) = nullptr;
};

/// Every cushion model, in the order CushionModel::names() gives. One line of registry.cpp
/// a model.
const std::vector<CushionModelDef>& cushionModels();

/// The model's definition.
const CushionModelDef& cushionModel(CushionModel m);

}  // namespace nineball::physics
