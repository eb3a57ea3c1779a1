#include "io/scene_json.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "common/limits.hpp"
#include "common/named.hpp"
#include "io/json_fields.hpp"
#include "io/json_reader.hpp"
#include "io/scene_parts.hpp"

namespace nineball::io {

using nlohmann::json;

namespace {

// Every range and its reason is in nineball/limits.hpp.
using limits::kMaxSpeed;
constexpr double kMaxTableSize = limits::kMaxTableLength;
constexpr double kMaxUntil = limits::kMaxSimTime;

}  // namespace

namespace {

// Names as a message quotes them: "9ft", "8ft" or "7ft".
std::string quotedList(const std::vector<std::string>& names) {
  std::vector<std::string> quoted;
  for (const std::string& name : names) quoted.push_back(quote(name));
  return listed(quoted);
}

// The pocket mouths and jaws of a custom table with pockets.
void parsePocketFields(const json& v, const std::string& path, TableDef& t) {
  for (auto [key, field] : {std::pair{"corner_pocket", &TableDef::corner_pocket},
                            std::pair{"side_pocket", &TableDef::side_pocket}}) {
    if (const json* p = optional(v, key)) {
      const std::string field_path = member(path, key);
      t.*field = number(*p, field_path, Bounds::positive());
      if (t.*field >= t.width / 2.0) refuse(field_path, "must be < table.width / 2");
    }
  }
  // A jaw below 90 degrees would point into the table; 180 would lie along the rail.
  const Bounds jaw{90.0, false, 180.0, true};
  if (const json* p = optional(v, "corner_jaw_deg")) {
    t.corner_jaw_deg = number(*p, "table.corner_jaw_deg", jaw);
  }
  if (const json* p = optional(v, "side_jaw_deg")) {
    t.side_jaw_deg = number(*p, "table.side_jaw_deg", jaw);
  }
  // A rounded jaw's knuckle: 0 is a sharp jaw point; checkTable refuses one too big to fit.
  for (auto [key, field] : {std::pair{"corner_jaw_radius", &TableDef::corner_jaw_radius},
                            std::pair{"side_jaw_radius", &TableDef::side_jaw_radius}}) {
    if (const json* p = optional(v, key)) {
      t.*field = number(*p, member(path, key), Bounds{0.0, false, t.width / 2.0, true});
    }
  }
}

}  // namespace

TableDef parseTable(const json& v) {
  const std::string path = "table";
  if (v.is_string()) {
    const std::string name = v.get<std::string>();
    if (auto named = TableDef::named(name)) return *named;
    std::vector<std::string> names = TableDef::names();
    for (std::string& n : names) n = quote(n);
    names.emplace_back("an object");
    refuse(path, "unknown table " + quote(name) + " (expected " + listed(names) + ")");
  }
  if (!v.is_object()) {
    refuse(path, "expected a table name or an object, found " + describe(v));
  }
  allowOnly(v, path,
            {"length", "width", "pockets", "corner_pocket", "side_pocket", "corner_jaw_deg",
             "side_jaw_deg", "corner_jaw_radius", "side_jaw_radius"});
  TableDef t;
  t.length = number(required(v, path, "length"), "table.length", Bounds::positive(kMaxTableSize));
  t.width = number(required(v, path, "width"), "table.width", Bounds::positive(kMaxTableSize));
  if (t.width > t.length) refuse("table.width", "must be <= table.length");
  if (const json* p = optional(v, "pockets")) {
    if (!p->is_boolean()) refuse("table.pockets", "expected true or false, found " + describe(*p));
    t.pockets = p->get<bool>();
  }
  if (!t.pockets) {
    for (const char* key : {"corner_pocket", "side_pocket", "corner_jaw_deg", "side_jaw_deg",
                            "corner_jaw_radius", "side_jaw_radius"}) {
      if (optional(v, key))
        refuse(member(path, key), "a table without pockets has no pocket mouths or jaws");
    }
    return t;
  }
  parsePocketFields(v, path, t);
  return t;
}

// The cloth models that read a parameter, so that one no model reads is refused, not ignored.
enum ClothUse : unsigned {
  kSpinCloth = 1u << static_cast<unsigned>(ClothModel::Spin),
  kFrictionCloth = 1u << static_cast<unsigned>(ClothModel::Friction),
  kDampingCloth = 1u << static_cast<unsigned>(ClothModel::Damping),
  kEveryCloth = kSpinCloth | kFrictionCloth | kDampingCloth,
};

struct ParamField {
  const char* name;
  double PhysicsParams::*field;
  Bounds bounds;
  unsigned used_by;
};

// Every parameter reaches Box2D as a float: the upper limits, far beyond any real table, keep
// it finite there (an infinite damping aborts the process in a Box2D assertion).
const Bounds kMass = Bounds::closed(limits::kMinBallMass, limits::kMaxBallMass);
// 0 is no squirt; a shaft end heavier than the heaviest ball is no cue.
const Bounds kEndMass = Bounds::closed(0.0, limits::kMaxBallMass);

const ParamField kParamFields[] = {
    {"ball_mass", &PhysicsParams::ball_mass, kMass, kEveryCloth},
    {"ball_radius", &PhysicsParams::ball_radius,
     Bounds::closed(limits::kMinBallRadius, limits::kMaxBallRadius), kEveryCloth},
    {"ball_restitution", &PhysicsParams::ball_restitution, Bounds::closed(0.0, 1.0), kEveryCloth},
    {"cushion_restitution", &PhysicsParams::cushion_restitution, Bounds::closed(0.0, 1.0),
     kEveryCloth},
    {"rolling_friction", &PhysicsParams::rolling_friction, Bounds::nonNegative(10.0),
     kSpinCloth | kFrictionCloth},
    {"sliding_friction", &PhysicsParams::sliding_friction, Bounds::nonNegative(10.0), kSpinCloth},
    {"spin_decay", &PhysicsParams::spin_decay, Bounds::nonNegative(1e4), kSpinCloth},
    {"cushion_friction", &PhysicsParams::cushion_friction, Bounds::nonNegative(10.0), kSpinCloth},
    {"miscue_limit", &PhysicsParams::miscue_limit, Bounds::closed(0.0, 1.0), kEveryCloth},
    {"cue_end_mass", &PhysicsParams::cue_end_mass, kEndMass, kEveryCloth},
    {"gravity", &PhysicsParams::gravity, Bounds::positive(1000.0), kSpinCloth | kFrictionCloth},
    {"linear_damping", &PhysicsParams::linear_damping, Bounds::nonNegative(1000.0), kDampingCloth},
    {"rest_speed", &PhysicsParams::rest_speed, Bounds::nonNegative(kMaxSpeed), kDampingCloth},
    {"table_restitution", &PhysicsParams::table_restitution, Bounds::closed(0.0, 1.0), kSpinCloth},
    {"min_bounce_height", &PhysicsParams::min_bounce_height, Bounds::nonNegative(1.0), kSpinCloth},
};

// Parameters only some cushion models read (the registry's `reads`): each refused, naming the
// models that read it, when the chosen one does not.
struct CushionParamField {
  const char* name;
  double PhysicsParams::*field;
  Bounds bounds;
};

const CushionParamField kCushionParamFields[] = {
    {"cushion_height", &PhysicsParams::cushion_height, Bounds::positive(1.0)},
    {"cushion_restitution_base", &PhysicsParams::cushion_restitution_base,
     Bounds::closed(0.0, 1.0)},
    {"cushion_restitution_slope", &PhysicsParams::cushion_restitution_slope,
     Bounds::closed(-limits::kMaxRestitutionSlope, limits::kMaxRestitutionSlope)},
    {"cushion_restitution_quadratic", &PhysicsParams::cushion_restitution_quadratic,
     Bounds::closed(-limits::kMaxRestitutionQuadratic, limits::kMaxRestitutionQuadratic)},
    {"cushion_restitution_min", &PhysicsParams::cushion_restitution_min, Bounds::closed(0.0, 1.0)},
};

// The contact orders, each a name of "physics" (sequential, simultaneous).
struct OrderField {
  const char* name;
  ContactOrder PhysicsParams::*field;
};

const OrderField kOrderFields[] = {{"frozen", &PhysicsParams::frozen},
                                   {"corner", &PhysicsParams::corner}};

// What reads a parameter, for the message that refuses one the chosen cloth does not read.
std::string clothsUsing(unsigned used_by) {
  std::string out;
  for (ClothModel m : {ClothModel::Spin, ClothModel::Friction, ClothModel::Damping}) {
    if (!(used_by & (1u << static_cast<unsigned>(m)))) continue;
    out += std::string(out.empty() ? "" : " or ") + quote(clothModelName(m));
  }
  return out;
}

// "a", "a" or "b", "a", "b" or "c": the names a field may take.
std::string oneOf(const std::vector<std::string>& names) {
  std::vector<std::string> quoted;
  for (const std::string& n : names) quoted.push_back(quote(n));
  return listed(quoted);
}

// The names of the models of one kind (CushionModel, BallBallModel) that read `parameter`.
template <class Model>
std::vector<std::string> modelsReading(const std::string& parameter) {
  std::vector<std::string> names;
  for (const std::string& name : Model::names()) {
    if (Model::named(name).reads(parameter)) names.push_back(name);
  }
  return names;
}

// A model chosen by name; an unknown name is refused with the names there are.
template <typename Model>
Model modelNamed(const json& v, const std::string& path,
                 std::optional<Model> (*from_name)(const std::string&), const char* what,
                 const char* expected) {
  const std::string name = text(v, path);
  const std::optional<Model> model = from_name(name);
  if (!model) {
    refuse(path, "unknown " + std::string(what) + " model " + quote(name) + " (expected " +
                     expected + ")");
  }
  return *model;
}

// A number is a constant coefficient; {"a", "b", "c"} is mu = a + b exp(-c v).
BallFriction parseBallFriction(const json& v, const std::string& path) {
  const Bounds coefficient = Bounds::closed(0.0, 1.0);
  if (v.is_number()) return {number(v, path, coefficient), 0.0, 0.0};
  if (!v.is_object()) {
    refuse(path,
           "expected a coefficient or {\"a\", \"b\", \"c\"} for mu = a + b exp(-c v), "
           "found " +
               describe(v));
  }
  allowOnly(v, path, {"a", "b", "c"});
  BallFriction f;
  f.a = number(required(v, path, "a"), member(path, "a"), coefficient);
  f.b = number(required(v, path, "b"), member(path, "b"), coefficient);
  f.c = number(required(v, path, "c"), member(path, "c"), Bounds::closed(0.0, 100.0));
  if (f.a + f.b > 1.0) refuse(path, "a + b (mu at rest) must be <= 1");
  return f;
}

nlohmann::ordered_json physicsToJson(const PhysicsParams& p) {
  nlohmann::ordered_json out;
  out["cloth"] = clothModelName(p.cloth);
  out["ball_ball"] = p.ball_ball.name();
  if (p.ball_ball.reads("ball_friction")) {
    out["ball_friction"] = {
        {"a", p.ball_friction.a}, {"b", p.ball_friction.b}, {"c", p.ball_friction.c}};
  }
  out["cushion"] = p.cushion.name();
  for (const CushionParamField& f : kCushionParamFields) {
    if (p.cushion.reads(f.name)) out[f.name] = p.*(f.field);
  }
  // The contact orders appear where they differ from one contact after the other.
  for (const OrderField& f : kOrderFields) {
    if (p.*(f.field) != ContactOrder::Sequential) out[f.name] = contactOrderName(p.*(f.field));
  }
  if (p.corner == ContactOrder::Simultaneous) out["cushion_contact_time"] = p.cushion_contact_time;
  if (p.frozen == ContactOrder::Simultaneous) out["frozen_tolerance"] = p.frozen_tolerance;
  out["pocket"] = pocketModelName(p.pocket);
  if (p.pocket == PocketModel::Fall) out["pocket_restitution"] = p.pocket_restitution;
  const unsigned cloth = 1u << static_cast<unsigned>(p.cloth);
  for (const ParamField& f : kParamFields) {
    if ((f.used_by & cloth) && !p.cushion.ignores(f.name)) out[f.name] = p.*(f.field);
  }
  return out;
}

PhysicsParams parsePhysics(const json& v) {
  const std::string path = "physics";
  expectObject(v, path);
  PhysicsParams p;
  // The preset is the base the overrides apply to, wherever it appears in the object.
  if (const json* preset = optional(v, "preset")) {
    const std::string name = text(*preset, "physics.preset");
    auto found = PhysicsParams::preset(name);
    if (!found) {
      refuse("physics.preset", "unknown preset " + quote(name) + " (expected " +
                                   quotedList(PhysicsParams::presetNames()) + ")");
    }
    p = *found;
  }
  for (const auto& item : v.items()) {
    const std::string& key = item.key();
    const std::string field_path = member(path, key);
    if (key == "preset") continue;
    if (key == "cloth") {
      p.cloth = modelNamed(item.value(), field_path, clothModelFromName, "cloth",
                           "\"spin\", \"friction\" or \"damping\"");
      continue;
    }
    if (key == "ball_ball") {
      p.ball_ball = modelNamed(item.value(), field_path, BallBallModel::fromName, "ball-ball",
                               oneOf(BallBallModel::names()).c_str());
      continue;
    }
    if (key == "ball_friction") {
      p.ball_friction = parseBallFriction(item.value(), field_path);
      continue;
    }
    if (key == "cushion") {
      p.cushion = modelNamed(item.value(), field_path, CushionModel::fromName, "cushion",
                             oneOf(CushionModel::names()).c_str());
      continue;
    }
    const auto* cf = std::find_if(std::begin(kCushionParamFields), std::end(kCushionParamFields),
                                  [&](const CushionParamField& f) { return key == f.name; });
    if (cf != std::end(kCushionParamFields)) {
      p.*(cf->field) = number(item.value(), field_path, cf->bounds);
      continue;
    }
    const auto* of = std::find_if(std::begin(kOrderFields), std::end(kOrderFields),
                                  [&](const OrderField& f) { return key == f.name; });
    if (of != std::end(kOrderFields)) {
      p.*(of->field) = modelNamed(item.value(), field_path, contactOrderFromName, of->name,
                                  "\"sequential\" or \"simultaneous\"");
      continue;
    }
    if (key == "pocket") {
      p.pocket = modelNamed(item.value(), field_path, pocketModelFromName, "pocket",
                            "\"fall\" or \"drop\"");
      continue;
    }
    if (key == "pocket_restitution") {
      p.pocket_restitution = number(item.value(), field_path, Bounds::closed(0.0, 1.0));
      continue;
    }
    if (key == "frozen_tolerance") {
      p.frozen_tolerance =
          number(item.value(), field_path, Bounds::nonNegative(limits::kMaxFrozenTolerance));
      continue;
    }
    if (key == "cushion_contact_time") {
      p.cushion_contact_time =
          number(item.value(), field_path, Bounds::positive(limits::kMaxCushionContactTime));
      continue;
    }
    const auto* f = std::find_if(std::begin(kParamFields), std::end(kParamFields),
                                 [&](const ParamField& pf) { return key == pf.name; });
    if (f == std::end(kParamFields)) {
      std::string list = "preset, cloth, ball_ball, ball_friction, cushion";
      for (const CushionParamField& c : kCushionParamFields) list += ", " + std::string(c.name);
      for (const OrderField& o : kOrderFields) list += ", " + std::string(o.name);
      list += ", cushion_contact_time, frozen_tolerance, pocket, pocket_restitution";
      for (const ParamField& pf : kParamFields) list += ", " + std::string(pf.name);
      refuse(field_path, "unknown parameter (expected one of: " + list + ")");
    }
    p.*(f->field) = number(item.value(), field_path, f->bounds);
  }
  // Each checked once the cushion is known, wherever "cushion" and "preset" appear. The
  // nose's range (between the ball's centre and top) is checkSettings's, with every setting.
  for (const CushionParamField& cf : kCushionParamFields) {
    if (!optional(v, cf.name) || p.cushion.reads(cf.name)) continue;
    refuse(member(path, cf.name), std::string("not used by the ") + quote(p.cushion.name()) +
                                      " cushion (only by " +
                                      oneOf(modelsReading<CushionModel>(cf.name)) + ")");
  }
  for (const ParamField& pf : kParamFields) {
    if (!optional(v, pf.name) || !p.cushion.ignores(pf.name)) continue;
    refuse(member(path, pf.name), std::string("not used by the ") + quote(p.cushion.name()) +
                                      " cushion (its restitution is a function of speed: "
                                      "cushion_restitution_base, _slope, _quadratic, _min)");
  }
  if (optional(v, "frozen_tolerance") && p.frozen != ContactOrder::Simultaneous) {
    refuse(member(path, "frozen_tolerance"),
           "not used by the \"sequential\" frozen ball (only by \"frozen\": \"simultaneous\")");
  }
  if (optional(v, "cushion_contact_time") && p.corner != ContactOrder::Simultaneous) {
    refuse(member(path, "cushion_contact_time"),
           "not used by the \"sequential\" corner (only by \"corner\": \"simultaneous\")");
  }
  if (optional(v, "pocket_restitution") && p.pocket != PocketModel::Fall) {
    refuse(member(path, "pocket_restitution"),
           "not used by the \"drop\" pocket (only by \"pocket\": \"fall\")");
  }
  if (!optional(v, "cushion_height") && optional(v, "ball_radius")) {
    p.cushion_height = 1.27 * p.ball_radius;  // 63.5 % of the diameter, as for the default ball
  }
  if (optional(v, "ball_friction") && !p.ball_ball.reads("ball_friction")) {
    refuse(member(path, "ball_friction"),
           std::string("not used by the ") + quote(p.ball_ball.name()) +
               " ball-ball model (only by " + oneOf(modelsReading<BallBallModel>("ball_friction")) +
               ")");
  }
  // Checked once the cloth is known, wherever "cloth" and "preset" appear in the object.
  for (const ParamField& pf : kParamFields) {
    if (!optional(v, pf.name) || (pf.used_by & (1u << static_cast<unsigned>(p.cloth)))) continue;
    refuse(member(path, pf.name), std::string("not used by the ") + quote(clothModelName(p.cloth)) +
                                      " cloth (only by the " + clothsUsing(pf.used_by) + " cloth)");
  }
  return p;
}

// "z" (m, the centre's height above resting on the cloth) and "vz" (m/s, up): a ball in the
// air, on the cloths that let one leave it.
void parseHeight(const json& b, const std::string& at, const PhysicsParams& physics,
                 BallState& ball) {
  if (const json* p = optional(b, "z")) {
    ball.z = number(*p, member(at, "z"), Bounds::closed(0.0, limits::kMaxBallHeight));
  }
  if (const json* p = optional(b, "vz")) {
    ball.vz = number(*p, member(at, "vz"), Bounds::closed(-kMaxSpeed, kMaxSpeed));
  }
  if (ball.z == 0.0 && ball.vz < 0.0) {
    refuse(member(at, "vz"), "a ball on the cloth cannot move down into the slate");
  }
  if ((ball.z != 0.0 || ball.vz != 0.0) && physics.cloth != ClothModel::Spin) {
    refuse(at,
           std::string("a ball leaves the cloth only on the \"spin\" cloth; this scene's is \"") +
               clothModelName(physics.cloth) + "\": drop \"z\" and \"vz\"");
  }
}

std::vector<BallState> parseBalls(const json& v, const PhysicsParams& physics) {
  const double radius = physics.ball_radius;
  const std::string path = "balls";
  if (!v.is_array()) refuse(path, "expected an array, found " + describe(v));
  if (v.size() > limits::kMaxBalls) {
    refuse(path, std::to_string(v.size()) + " balls, more than the " +
                     std::to_string(limits::kMaxBalls) + " a scene may hold");
  }
  std::vector<BallState> balls;
  std::map<int, std::size_t> index_of_id;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const json& b = v[i];
    const std::string at = element(path, i);
    expectObject(b, at);
    allowOnly(b, at, {"id", "x", "y", "vx", "vy", "z", "vz", "w", "mass"});
    BallState ball;
    ball.id = integer(required(b, at, "id"), member(at, "id"), 0, INT_MAX);
    const auto [seen, fresh] = index_of_id.emplace(ball.id, i);
    if (!fresh) {
      refuse(member(at, "id"), "duplicate id " + std::to_string(ball.id) + " (also " +
                                   element(path, seen->second) + ")");
    }
    ball.pos.x = number(required(b, at, "x"), member(at, "x"));
    ball.pos.y = number(required(b, at, "y"), member(at, "y"));
    if (const json* p = optional(b, "vx")) ball.vel.x = number(*p, member(at, "vx"));
    if (const json* p = optional(b, "vy")) ball.vel.y = number(*p, member(at, "vy"));
    if (std::hypot(ball.vel.x, ball.vel.y) > kMaxSpeed) {
      refuse(at, "speed hypot(vx, vy) must be <= " + formatNumber(kMaxSpeed) + " m/s");
    }
    parseHeight(b, at, physics, ball);
    if (const json* p = optional(b, "w")) {
      const std::string wpath = member(at, "w");
      if (!p->is_array() || p->size() != 3) {
        refuse(wpath, "expected [wx, wy, wz] in rad/s, found " + describe(*p));
      }
      // No cue gives the ball's surface more speed than a strike at its edge at top speed.
      const double w_max = limits::kMaxSurfaceSpeed / radius;
      const Bounds spin = Bounds::closed(-w_max, w_max);
      ball.w = {number((*p)[0], element(wpath, 0), spin), number((*p)[1], element(wpath, 1), spin),
                number((*p)[2], element(wpath, 2), spin)};
    }
    if (const json* p = optional(b, "mass")) {
      ball.mass = number(*p, member(at, "mass"), kMass);
    }
    balls.push_back(ball);
  }
  return balls;
}

Vec2 parseTip(const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 2) {
    refuse(path, "expected an array of two numbers [side, height], found " + describe(v));
  }
  const Bounds fraction = Bounds::closed(-1.0, 1.0);
  const Vec2 tip{number(v[0], element(path, 0), fraction),
                 number(v[1], element(path, 1), fraction)};
  if (dot(tip, tip) > 1.0) refuse(path, "must lie on the ball: side^2 + height^2 <= 1");
  return tip;
}

namespace {

// "heading_deg", or "heading_rad" (the exact radians a result prints, which degrees written out
// in decimal do not give back bit for bit): one of them, in degrees for Shot's makers.
double headingField(const json& v, const std::string& path, std::optional<double>& exact_rad) {
  const json* rad = optional(v, "heading_rad");
  if (!rad) return number(required(v, path, "heading_deg"), member(path, "heading_deg"));
  if (optional(v, "heading_deg")) {
    refuse(path, "give either \"heading_deg\" or \"heading_rad\", not both");
  }
  exact_rad = number(*rad, member(path, "heading_rad"));
  return radToDeg(*exact_rad);
}

}  // namespace

Shot parseShotFields(const json& v, const std::string& path, double cue_mass) {
  std::optional<double> exact_rad;
  const double heading = headingField(v, path, exact_rad);
  const json* speed = optional(v, "speed");
  const json* force = optional(v, "force");
  const json* contact_time = optional(v, "contact_time");
  Shot shot;
  if (speed) {
    if (force || contact_time) {
      refuse(path, "give either \"speed\" or \"force\" and \"contact_time\", not both");
    }
    shot = Shot::withSpeed(heading,
                           number(*speed, member(path, "speed"), Bounds::nonNegative(kMaxSpeed)));
  } else {
    if (!force && !contact_time) refuse(path, "needs \"speed\" or \"force\" and \"contact_time\"");
    if (!force) refuse(member(path, "force"), "required with \"contact_time\"");
    if (!contact_time) refuse(member(path, "contact_time"), "required with \"force\"");
    const double f = number(*force, member(path, "force"), Bounds::positive());
    const double dt = number(*contact_time, member(path, "contact_time"), Bounds::positive());
    shot = Shot::withImpulse(heading, f, dt, cue_mass);
    if (!(shot.speed <= kMaxSpeed)) {
      refuse(path, "force * contact_time / mass gives " + formatNumber(shot.speed) +
                       " m/s, more than " + formatNumber(kMaxSpeed));
    }
  }
  // The radians as given, to the bit (Shot's makers go through degrees).
  if (exact_rad) shot.heading_rad = *exact_rad;
  if (const json* tip = optional(v, "tip")) shot.tip = parseTip(*tip, member(path, "tip"));
  const json* elevation_rad = optional(v, "elevation_rad");
  if (elevation_rad) {
    if (optional(v, "elevation_deg")) {
      refuse(path, "give either \"elevation_deg\" or \"elevation_rad\", not both");
    }
    shot.elevation_rad =
        number(*elevation_rad, member(path, "elevation_rad"), Bounds::closed(0.0, degToRad(89.0)));
  } else if (const json* e = optional(v, "elevation_deg")) {
    // 90 degrees would drive the ball straight into the slate: no horizontal motion at all.
    shot.elevation_rad =
        degToRad(number(*e, member(path, "elevation_deg"), Bounds::closed(0.0, 89.0)));
  }
  return shot;
}

namespace {

Shot parseShot(const json& v, const std::vector<BallState>& balls, const PhysicsParams& physics) {
  const std::string path = "shot";
  expectObject(v, path);
  allowOnly(v, path,
            {"heading_deg", "heading_rad", "speed", "force", "contact_time", "tip", "elevation_deg",
             "elevation_rad"});
  const auto cue =
      std::find_if(balls.begin(), balls.end(), [](const BallState& b) { return b.id == kCueBall; });
  if (cue == balls.end()) refuse(path, "needs a cue ball (a ball with id 0)");
  return parseShotFields(v, path, cue->mass.value_or(physics.ball_mass));
}

std::optional<double> parseUntil(const json& v) {
  if (v.is_string() && v.get<std::string>() == "rest") return std::nullopt;
  if (!v.is_number()) {
    refuse("until", "expected \"rest\" or a number of seconds, found " + describe(v));
  }
  return number(v, "until", Bounds::positive(kMaxUntil));
}

TraceRequest parseTrace(const json& v) {
  const std::string path = "trace";
  expectObject(v, path);
  allowOnly(v, path, {"hz", "events_only"});
  const json* hz = optional(v, "hz");
  const json* events_only = optional(v, "events_only");
  if (hz && events_only) {
    refuse(path, "give either \"hz\" or \"events_only\", not both");
  }
  TraceRequest t;
  if (hz) {
    t.hz = number(*hz, "trace.hz");
    if (!(t.hz >= limits::kMinTraceHz && t.hz <= limits::kMaxTraceHz)) {
      refuse("trace.hz", "must be >= " + formatNumber(limits::kMinTraceHz) +
                             " and <= " + formatNumber(limits::kMaxTraceHz) +
                             " samples per second, found " + describe(*hz) +
                             " (a trace holds at most " + std::to_string(limits::kMaxTraceSamples) +
                             " samples, balls x instants, and ends early beyond that)");
    }
    return t;
  }
  if (events_only) {
    if (!events_only->is_boolean() || !events_only->get<bool>()) {
      refuse("trace.events_only",
             "expected true (for samples at a rate give \"hz\" instead), found " +
                 describe(*events_only));
    }
    t.events_only = true;
    return t;
  }
  refuse(path, "needs \"hz\" (samples per second) or \"events_only\": true");
}

}  // namespace

StepParams parseStep(const json& v) {
  const std::string path = "step";
  expectObject(v, path);
  allowOnly(v, path,
            {"hz", "velocity_iterations", "position_iterations", "scale", "contacts", "engine",
             "max_time", "baseline"});
  StepParams s;
  if (const json* p = optional(v, "hz")) {
    s.hz = number(*p, "step.hz", Bounds::closed(limits::kMinHz, limits::kMaxHz));
  }
  if (const json* p = optional(v, "velocity_iterations")) {
    s.box2d.velocity_iterations = integer(*p, "step.velocity_iterations", 1, 100);
  }
  if (const json* p = optional(v, "position_iterations")) {
    s.box2d.position_iterations = integer(*p, "step.position_iterations", 0, 100);
  }
  if (const json* p = optional(v, "scale")) {
    s.box2d.scale = number(*p, "step.scale", Bounds::closed(limits::kMinScale, limits::kMaxScale));
  }
  if (const json* p = optional(v, "contacts")) {
    const std::string name = text(*p, "step.contacts");
    auto model = contactModelFromName(name);
    if (!model) {
      refuse("step.contacts",
             "unknown contact model " + quote(name) + " (expected \"pairwise\" or \"box2d\")");
    }
    s.box2d.contacts = *model;
  }
  if (const json* p = optional(v, "engine")) {
    const std::string name = text(*p, "step.engine");
    auto engine = EngineKind::fromName(name);
    if (!engine) {
      refuse("step.engine",
             "unknown engine " + quote(name) + " (expected " + oneOf(EngineKind::names()) + ")");
    }
    s.engine = *engine;
  }
  if (const json* p = optional(v, "baseline")) {
    if (!p->is_boolean()) refuse("step.baseline", "expected true or false, found " + describe(*p));
    s.baseline = p->get<bool>();
    // The baseline steps at the finest rate unless a rate is given.
    if (s.baseline && !optional(v, "hz")) s.hz = StepParams::kBaselineHz;
  }
  if (const json* p = optional(v, "max_time")) {
    s.max_time = number(*p, "step.max_time", Bounds::positive(limits::kMaxSimTime));
  }
  return s;
}

namespace {

// Fields that only some settings read: given where nothing reads them, they are refused, so
// that no value is silently ignored.
void refuseWhatNothingReads(const json& doc, const Scene& scene) {
  if (!scene.physics.spin()) {
    const json& balls = doc.at("balls");
    for (std::size_t i = 0; i < balls.size(); ++i) {
      if (scene.balls[i].w == Vec3{}) continue;
      refuse("balls[" + std::to_string(i) + "].w",
             "the " + quote(clothModelName(scene.physics.cloth)) +
                 " cloth carries no spin (only the \"spin\" cloth does)");
    }
  }
  const json* step = optional(doc, "step");
  if (!step) return;
  for (const char* key :
       {"hz", "velocity_iterations", "position_iterations", "scale", "contacts", "baseline"}) {
    if (!optional(*step, key) || scene.step.engine.reads(key)) continue;
    std::vector<std::string> readers;
    for (const std::string& name : EngineKind::names()) {
      if (EngineKind::named(name).reads(key)) readers.push_back(name);
    }
    refuse(member("step", key), std::string("not used by the ") + scene.step.engine.name() +
                                    " engine, which " + scene.step.engine.lacks() +
                                    " (only by the " + oneOf(readers) + " engine)");
  }
}

Scene parseSceneDocument(const json& doc) {
  if (!doc.is_object()) refuse("scene", "expected an object, found " + describe(doc));
  allowOnly(doc, "", {"table", "physics", "balls", "shot", "until", "step", "trace"});
  Scene scene;
  if (const json* p = optional(doc, "table")) scene.table = parseTable(*p);
  if (const json* p = optional(doc, "physics")) scene.physics = parsePhysics(*p);
  scene.balls = parseBalls(required(doc, "", "balls"), scene.physics);
  if (const json* p = optional(doc, "shot")) scene.shot = parseShot(*p, scene.balls, scene.physics);
  if (const json* p = optional(doc, "until")) scene.until = parseUntil(*p);
  if (const json* p = optional(doc, "step")) scene.step = parseStep(*p);
  if (const json* p = optional(doc, "trace")) scene.trace = parseTrace(*p);
  refuseWhatNothingReads(doc, scene);
  if (auto problem = validateScene(scene)) throw ParseError{*problem};
  return scene;
}

}  // namespace

SceneResult parseScene(std::string_view text) {
  try {
    return parseSceneDocument(readJson(text));
  } catch (const ParseError& e) {
    return e;
  }
}

SceneResult sceneFromJson(const nlohmann::json& doc) {
  try {
    return parseSceneDocument(doc);
  } catch (const ParseError& e) {
    return e;
  }
}

}  // namespace nineball::io
