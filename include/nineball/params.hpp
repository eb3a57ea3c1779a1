#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "nineball/box2d_settings.hpp"
#include "nineball/named_choice.hpp"

namespace nineball {

/// How the cloth slows a ball.
enum class ClothModel {
  Spin,      ///< sliding friction on the contact point's slip, then rolling resistance
  Friction,  ///< constant deceleration mu g against the velocity (paper eq. 4.5-4.8)
  Damping,   ///< Box2D linear damping: v <- v / (1 + h c) each step
};

/// How balls grip each other while they touch: one of the ball-ball models of the registry
/// (src/physics/resolve/ball_ball/registry.cpp), chosen by the name it declares there
/// ("frictionless", the paper's: the impulse along the line of centres only; "frictional",
/// friction of the contact points: throw and spin transfer).
class BallBallModel : public NamedChoice<BallBallModel> {
 public:
  static constexpr const char* kWhat = "ball-ball model";
  /// True when it reads `parameter` (a field of "physics" that only some ball-ball models read).
  bool reads(const std::string& parameter) const;

 private:
  friend class NamedChoice<BallBallModel>;
  explicit BallBallModel(std::size_t index) : NamedChoice(index) {}
  // Its registry (src/physics/resolve/ball_ball/registry.cpp).
  static std::size_t registrySize();
  static const char* registryName(std::size_t index);
};

/// How a cushion sends a ball back: one of the cushion models of the registry
/// (src/physics/resolve/cushion/registry.cpp), chosen by the name it declares there ("simple",
/// the paper's; "mathavan", Mathavan et al. 2010; ...).
class CushionModel : public NamedChoice<CushionModel> {
 public:
  static constexpr const char* kWhat = "cushion model";
  /// True when it reads `parameter` (a field of "physics" that only some cushion models read).
  bool reads(const std::string& parameter) const;
  /// True when it does not read `parameter`, a field the other cushion models read
  /// ("cushion_restitution" for a model whose restitution is a function of speed).
  bool ignores(const std::string& parameter) const;

 private:
  friend class NamedChoice<CushionModel>;
  explicit CushionModel(std::size_t index) : NamedChoice(index) {}
  // Its registry (src/physics/resolve/cushion/registry.cpp).
  static std::size_t registrySize();
  static const char* registryName(std::size_t index);
};

/// Ball-ball friction against the sliding speed v (m/s) of the contact points:
/// mu = a + b exp(-c v), Alciatore's fit of measured throw (TP A.14); b = 0 for a constant.
struct BallFriction {
  double a = 9.951e-3;
  double b = 0.108;
  double c = 1.088;

  double at(double sliding) const { return a + b * std::exp(-c * sliding); }
};

/// What happens once a ball's centre crosses a pocket's fall edge, the edge of the slate
/// (docs/physics.md, "Pockets: falling, the back and bouncing out").
enum class PocketModel {
  Drop,  ///< pocketed at once, whatever its speed (the model before issue 34; the paper's)
  Fall,  ///< falls as a projectile: caught, or thrown back out by the pocket's back and facings
};

/// How contacts that meet within one contact are resolved: one after the other, each with its
/// own model (the paper's way, and the default), or their normal impulses solved together.
enum class ContactOrder {
  Sequential,    ///< one contact after the other
  Simultaneous,  ///< the normal impulses of both contacts from one linear complementarity problem
};

/// Which engine runs a scene: one of the engines of the registry
/// (src/physics/engines/registry.cpp), chosen by the name it declares there ("box2d", Box2D's
/// bodies and pieces; "reference", the exact event-based solver with no time step).
class EngineKind : public NamedChoice<EngineKind> {
 public:
  static constexpr const char* kWhat = "engine";
  /// True when it reads `field` of the scene's "step" (its solver settings).
  bool reads(const std::string& field) const;
  /// What it lacks that the fields it does not read are for ("has no time step"), to say why
  /// a scene that sets one is refused.
  const char* lacks() const;

 private:
  friend class NamedChoice<EngineKind>;
  explicit EngineKind(std::size_t index) : NamedChoice(index) {}
  // Its registry (src/physics/engines/registry.cpp).
  static std::size_t registrySize();
  static const char* registryName(std::size_t index);
};

/// Physical parameters, SI units. Every field can be overridden in a scene.
struct PhysicsParams {
  double ball_mass = 0.170;           ///< kg (WPA 156-170 g)
  double ball_radius = 0.028575;      ///< m (2.25 in diameter)
  double ball_restitution = 0.95;     ///< ball-ball e (0.92-0.98)
  double cushion_restitution = 0.85;  ///< ball-cushion e (0.6-0.9)
  double rolling_friction = 0.01;     ///< mu of the cloth model (rolling resistance)
  double sliding_friction = 0.2;      ///< mu of a sliding ball (spin model)
  double cushion_friction = 0.2;      ///< mu between ball and cushion nose (spin model)
  double spin_decay = 10.0;           ///< rad/s^2, decay of spin about the vertical
  double gravity = 9.81;              ///< m/s^2
  double linear_damping = 0.2;        ///< 1/s, the damping model's c
  double rest_speed = 0.001;          ///< m/s, below which the damping model stops a ball
  ClothModel cloth = ClothModel::Spin;
  BallBallModel ball_ball = BallBallModel::named("frictional");
  BallFriction ball_friction;  ///< read by the frictional ball-ball model
  CushionModel cushion = CushionModel::named("mathavan");
  /// m, the cushion's nose above the slate (WPA: 62.5-64.5 % of the ball's diameter); read by
  /// the cushion models that model the nose (the registry says which). Follows ball_radius in a
  /// scene that sets only the radius.
  double cushion_height = 1.27 * 0.028575;
  /// The restitution of the speed-dependent cushion ("mathavan_speed"), a function of the
  /// normal approach speed V (m/s): e(V) = base + slope V + quadratic V^2, held within
  /// [restitution_min, 1]. Han 2005's fit to measured rebounds (his eq. 26): 0.39, 0.257 s/m,
  /// -0.044 s^2/m^2, and the floor 0.40 that pooltool and other simulators give it.
  double cushion_restitution_base = 0.39;
  double cushion_restitution_slope = 0.257;       ///< s/m
  double cushion_restitution_quadratic = -0.044;  ///< s^2/m^2
  double cushion_restitution_min = 0.40;
  /// A ball touching a cushion when another ball strikes it (a frozen ball).
  ContactOrder frozen = ContactOrder::Sequential;
  /// m, how near a cushion a struck ball counts as frozen to it (0: touching, within the
  /// engines' touch tolerance); read by "frozen": "simultaneous" only. A tracked ball's place
  /// is known to a millimetre or so, never to the touch.
  double frozen_tolerance = 0.0;
  /// A ball meeting a second cushion within cushion_contact_time of the first (a corner, a jaw).
  ContactOrder corner = ContactOrder::Sequential;
  /// s, how long a ball stays in a cushion; read by "corner": "simultaneous" only.
  double cushion_contact_time = 0.01;
  /// What a pocket does with a ball whose centre crosses its fall edge.
  PocketModel pocket = PocketModel::Fall;
  /// The normal restitution of a pocket's back and facings met by a falling ball (the liner,
  /// leather and rubber over wood); read by "pocket": "fall" only. An estimate: see
  /// docs/physics.md, "Pockets".
  double pocket_restitution = 0.5;
  /// The slate's restitution for a ball landing on it or driven into it by the cue (a bounce's
  /// height falls by its square). pooltool's default, 0.5; docs/physics.md, "Balls in the air".
  double table_restitution = 0.5;
  /// m, the least height a bounce must lift the ball's bottom for it to leave the cloth; a
  /// lower one ends the bouncing (pooltool's 5 mm).
  double min_bounce_height = 0.005;
  double miscue_limit = 0.5;           ///< largest tip offset (fraction of R) that is a hit
  double cue_end_mass = 0.170 / 30.0;  ///< kg, the shaft's effective end mass (squirt; 0: none)

  /// True when balls carry spin (the Spin cloth model).
  bool spin() const { return cloth == ClothModel::Spin; }

  /// Real equipment (WPA, Alciatore, pooltool defaults).
  static PhysicsParams real() { return {}; }
  /// The seed paper's values: m 0.16 kg, ball e 0.9, rail keeps 70 % of the normal speed,
  /// mu m g on the cloth and nothing else (no spin).
  static PhysicsParams paper();
  /// Carom equipment (UMB balls, a heated carom cloth), the real models.
  static PhysicsParams carom();
  /// Snooker equipment (WPBSA balls, a napped snooker cloth, snooker cushions), the real models.
  static PhysicsParams snooker();
  /// A preset by the name scenes give it (presetNames()); nothing for another.
  static std::optional<PhysicsParams> preset(const std::string& name);
  /// Every preset's name: "real", "paper", "carom".
  static std::vector<std::string> presetNames();
};

/// How a run is stepped, whichever engine runs it; what one engine alone reads is grouped by
/// engine (box2d).
struct StepParams {
  double hz = 60.0;  ///< base step rate: where stepping stops (a frame); events fall between
  EngineKind engine = EngineKind::named("box2d");
  double max_time = 600.0;  ///< s, a run to rest gives up after this long
  /// The plain fixed-rate reference: every ball, resting or not, stepped at every step, no
  /// skipping of idle work. Steps still split where a ball would outrun Box2D's travel limit.
  bool baseline = false;
  Box2DSettings box2d;  ///< read by the box2d engine only

  /// The baseline as measured against: every ball at the finest rate of the sweep.
  static StepParams plainBaseline() {
    StepParams s;
    s.hz = kBaselineHz;
    s.baseline = true;
    return s;
  }
  static constexpr double kBaselineHz = 2000.0;

  double dt() const { return 1.0 / hz; }
};

const char* clothModelName(ClothModel m);
const char* contactOrderName(ContactOrder o);
const char* pocketModelName(PocketModel m);
std::optional<PocketModel> pocketModelFromName(const std::string& name);
std::optional<ContactOrder> contactOrderFromName(const std::string& name);
std::optional<ClothModel> clothModelFromName(const std::string& name);

}  // namespace nineball
