#include "nineball/params.hpp"

namespace nineball {

PhysicsParams PhysicsParams::paper() {
  PhysicsParams p;
  p.ball_mass = 0.16;
  p.ball_restitution = 0.9;
  p.cushion_restitution = 0.7;
  // The paper's own mu was in program units; the real rolling resistance stands in for it.
  p.rolling_friction = 0.01;
  p.cloth = ClothModel::Friction;
  p.ball_ball = BallBallModel::named("frictionless");
  p.cue_end_mass = 0.0;
  p.cushion = CushionModel::named("simple");
  return p;
}

std::optional<PhysicsParams> PhysicsParams::preset(const std::string& name) {
  if (name == "real") return real();
  if (name == "paper") return paper();
  return std::nullopt;
}

const char* clothModelName(ClothModel m) {
  switch (m) {
    case ClothModel::Spin:
      return "spin";
    case ClothModel::Friction:
      return "friction";
    case ClothModel::Damping:
      return "damping";
  }
  return "?";
}

const char* contactModelName(ContactModel m) {
  return m == ContactModel::Pairwise ? "pairwise" : "box2d";
}

std::optional<ClothModel> clothModelFromName(const std::string& name) {
  if (name == "spin") return ClothModel::Spin;
  if (name == "friction") return ClothModel::Friction;
  if (name == "damping") return ClothModel::Damping;
  return std::nullopt;
}

std::optional<ContactModel> contactModelFromName(const std::string& name) {
  if (name == "pairwise") return ContactModel::Pairwise;
  if (name == "box2d") return ContactModel::Box2D;
  return std::nullopt;
}

}  // namespace nineball
