#pragma once

#include <optional>
#include <string>

namespace nineball {

/// How ball-ball contacts are resolved by the box2d engine.
enum class ContactModel {
  Pairwise,  ///< exact time of impact inside the step, one pair at a time, the paper's formulas
  Box2D,     ///< Box2D's own simultaneous contact solver
};

/// What only the box2d engine reads: its solver's iterations, its units and who solves ball-ball
/// contacts (a scene's "step": velocity_iterations, position_iterations, scale, contacts). The
/// reference engine has no use for them, and a scene that sets one for it is refused.
struct Box2DSettings {
  int velocity_iterations = 8;
  int position_iterations = 3;
  double scale = 50.0;  ///< Box2D units per metre (k)
  ContactModel contacts = ContactModel::Pairwise;
};

const char* contactModelName(ContactModel m);
std::optional<ContactModel> contactModelFromName(const std::string& name);

}  // namespace nineball
