#include "nineball/params.hpp"

#include <string>
#include <vector>

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
  // The paper pockets a ball the moment its centre is over the hole.
  p.pocket = PocketModel::Drop;
  return p;
}

PhysicsParams PhysicsParams::carom() {
  PhysicsParams p;  // the real models: throw, squirt, swerve, Mathavan's cushion
  // UMB equipment rules: balls of 61 to 61.5 mm and 205 to 220 g.
  p.ball_radius = 0.0615 / 2.0;
  p.ball_mass = 0.210;
  // UMB: the cushion's nose 37 mm (+-1) above the slate, 60 % of the ball's diameter.
  p.cushion_height = 0.037;
  // The heated carom cloth is fast: tracked carom shots roll out at about 0.05 m/s^2, a
  // rolling resistance of 0.005, half a pool cloth's (shared/physics-models.md).
  p.rolling_friction = 0.005;
  // No published measurement of a sliding carom ball was found; the worsted cloth's 0.2
  // (Alciatore TP 4.1, pooltool's u_s) stands in, as for pool.
  p.sliding_friction = 0.2;
  // Carom cushions are fitted to the taller ball and played hard and long: Mathavan's
  // measured ball-cushion values (e 0.98 for the model's own restitution, mu 0.14; Mathavan,
  // Jackson and Parkin 2010) rather than pool's livelier-rubber defaults.
  p.cushion_restitution = 0.98;
  p.cushion_friction = 0.14;
  // The cue: the same shaft end (its mass in kg) against a heavier ball squirts less.
  return p;
}

PhysicsParams PhysicsParams::snooker() {
  PhysicsParams p;  // the real models: throw, squirt, swerve, Mathavan's cushion
  // WPBSA Official Rules, section 2: balls of 52.5 mm (+-0.05 mm), a set equal in weight
  // within 3 g; a typical set weighs 141-142 g each (shared/physics-models.md: about 142 g).
  p.ball_radius = 0.0525 / 2.0;
  p.ball_mass = 0.142;
  // The cushion's nose at the pool ratio of the ball (1.27 R, 33 mm): no published snooker
  // figure was found; the cushion is cut to the ball as pool's is.
  p.cushion_height = 1.27 * p.ball_radius;
  // Mathavan, Jackson and Parkin, "Application of high-speed imaging to determine the
  // dynamics of billiards", Am. J. Phys. 77 (2009) 788: snooker balls tracked on a napped
  // snooker cloth gave a sliding coefficient of 0.212 and a rolling one of 0.0127.
  p.sliding_friction = 0.212;
  p.rolling_friction = 0.0127;
  // Mathavan, Jackson and Parkin 2010 (Proc. IMechE C 224, 1863), measured on a snooker
  // table: their cushion model fits the rebounds with e 0.98 and a ball-cushion mu of 0.14.
  p.cushion_restitution = 0.98;
  p.cushion_friction = 0.14;
  // Ball-ball: the phenolic balls are the same make as pool's (Aramith); pool's measured
  // restitution (0.95) and throw friction (Alciatore's fit, the default) stand. The cue's end
  // mass stays pool's: against the lighter ball the same shaft squirts it more.
  return p;
}

namespace {

struct NamedPreset {
  const char* name;
  PhysicsParams (*make)();
};

// The one list of presets: a name here is known everywhere a scene's physics is read.
const std::vector<NamedPreset>& presets() {
  static const std::vector<NamedPreset> list{{"real", &PhysicsParams::real},
                                             {"paper", &PhysicsParams::paper},
                                             {"carom", &PhysicsParams::carom},
                                             {"snooker", &PhysicsParams::snooker}};
  return list;
}

}  // namespace

std::optional<PhysicsParams> PhysicsParams::preset(const std::string& name) {
  for (const NamedPreset& p : presets()) {
    if (name == p.name) return p.make();
  }
  return std::nullopt;
}

std::vector<std::string> PhysicsParams::presetNames() {
  std::vector<std::string> out;
  for (const NamedPreset& p : presets()) out.emplace_back(p.name);
  return out;
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

const char* contactOrderName(ContactOrder o) {
  return o == ContactOrder::Sequential ? "sequential" : "simultaneous";
}

std::optional<ContactOrder> contactOrderFromName(const std::string& name) {
  if (name == "sequential") return ContactOrder::Sequential;
  if (name == "simultaneous") return ContactOrder::Simultaneous;
  return std::nullopt;
}

const char* pocketModelName(PocketModel m) {
  return m == PocketModel::Drop ? "drop" : "fall";
}

std::optional<PocketModel> pocketModelFromName(const std::string& name) {
  if (name == "drop") return PocketModel::Drop;
  if (name == "fall") return PocketModel::Fall;
  return std::nullopt;
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
