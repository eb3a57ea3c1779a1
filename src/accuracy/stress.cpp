#include "accuracy/stress.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "common/limits.hpp"
#include "nineball/engine.hpp"
#include "nineball/random.hpp"
#include "nineball/scenes.hpp"
#include "nineball/sim.hpp"
#include "nineball/state_hash.hpp"
#include "physics/model/motion.hpp"
#include "physics/model/slate.hpp"

namespace nineball {
namespace {

// Limits of the checks, from the issue: 0.1 mm of overlap between balls; the same for how
// far a ball may sink into a cushion; energy may wobble by the rounding of Box2D's single-
// precision velocities only.
constexpr double kMaxOverlap = 1e-4;
constexpr double kMaxSink = 1e-4;
constexpr double kEnergyRounding = 1e-6;
constexpr std::size_t kFailuresKept = 10;

struct Scenario {
  std::string kind;
  std::string name;
  TableDef table;
  PhysicsParams physics;
  StepParams step;
  std::vector<BallState> balls;
  std::optional<Shot> shot;
  double run_s = 0.0;       // 0: until rest (must come within rest_within_s)
  bool fixed_step = false;  // keeps its own step settings, not the command's
};

// Kinetic energy with rotation, and the height's potential energy: a flight trades one for
// the other.
double energy(const std::vector<BallState>& balls, double r, double mass, double g) {
  double e = 0.0;
  for (const BallState& b : balls) {
    if (b.pocket) continue;
    e += physics::mechanicalEnergy({b.pos, b.vel, b.w, b.z, b.vz}, b.mass.value_or(mass), r, g);
  }
  return e;
}

// A ball off the table is announced by the event that took it: a pocket, or over a rail.
bool announcedOff(const BallState& b, const std::vector<Event>& events, std::size_t from) {
  const EventType type = b.off_table ? EventType::OffTable : EventType::Pocket;
  for (std::size_t k = from; k < events.size(); ++k) {
    if (events[k].type == type && events[k].a == b.id) return true;
  }
  return false;
}

bool finite(const BallState& b) {
  return std::isfinite(b.pos.x) && std::isfinite(b.pos.y) && std::isfinite(b.vel.x) &&
         std::isfinite(b.vel.y) && std::isfinite(b.w.x) && std::isfinite(b.w.y) &&
         std::isfinite(b.w.z);
}

class Checker {
 public:
  Checker(StressReport& report, std::string scenario)
      : report_(report), name_(std::move(scenario)) {}

  void check(const char* what, bool ok, const std::string& detail = "") {
    ++report_.checks;
    if (ok) return;
    ++report_.failures[what];
    // The first failure of each scenario, so that one bad scene cannot hide the others.
    if (!told_ && report_.first_failures.size() < kFailuresKept) {
      told_ = true;
      report_.first_failures.push_back(name_ + ": " + what + (detail.empty() ? "" : " " + detail));
    }
  }

 private:
  StressReport& report_;
  std::string name_;
  bool told_ = false;
};

// One run; returns a fingerprint of everything it produced, for the twin-run comparison.
std::uint64_t runOnce(const Scenario& s, const StressOptions& o, StressReport& report, bool count) {
  StressReport scratch;
  StressReport& rep = count ? report : scratch;
  Checker check(rep, s.name);
  const std::unique_ptr<Engine> w_engine = makeEngine(s.table, s.physics, s.step);
  Engine& w = *w_engine;
  for (const BallState& b : s.balls) w.addBall(b);
  if (s.shot) w.strike(kCueBall, *s.shot);
  const double r = s.physics.ball_radius;
  double e_prev = energy(w.balls(), r, s.physics.ball_mass, s.physics.gravity);
  BitHash hash;
  auto mix = [&hash](double v) { hash.add(v); };
  const double limit = s.run_s > 0.0 ? s.run_s : o.rest_within_s;
  std::size_t events_seen = 0;
  std::vector<bool> was_pocketed(s.balls.size(), false);
  while (w.time() < limit && (s.run_s > 0.0 || !w.atRest()) && !w.exhausted()) {
    w.step();
    if (count) ++rep.steps;
    const std::vector<BallState> balls = w.balls();
    const auto& events = w.events();
    for (std::size_t i = 0; i < balls.size(); ++i) {
      const BallState& b = balls[i];
      mix(b.pos.x);
      mix(b.pos.y);
      check.check("finite", finite(b), "ball " + std::to_string(b.id));
      if (b.pocket) {
        if (!was_pocketed[i]) {
          check.check("off the table with an event", announcedOff(b, events, events_seen),
                      "ball " + std::to_string(b.id));
          was_pocketed[i] = true;
        }
        continue;
      }
      check.check("inside the cushions", w.table().insideLoop(b.pos),
                  "ball " + std::to_string(b.id));
      check.check("never through the slate", b.z >= 0.0, "ball " + std::to_string(b.id));
      check.check("not sunk into a cushion", cushionSink(w.table(), b.pos, r) <= kMaxSink,
                  "ball " + std::to_string(b.id));
      for (std::size_t j = i + 1; j < balls.size(); ++j) {
        if (balls[j].pocket) continue;
        const double gap = centreDistance(b, balls[j]) - 2.0 * r;
        if (gap > 0.01) continue;
        if (gap >= -kMaxOverlap) {
          check.check("no overlap", true);
          continue;
        }
        std::ostringstream what;
        what << "balls " << b.id << "," << balls[j].id << " by " << -gap * 1e3 << " mm at t "
             << w.time() << " s";
        check.check("no overlap", false, what.str());
      }
    }
    events_seen = events.size();
    const double e = energy(balls, r, s.physics.ball_mass, s.physics.gravity);
    check.check("energy never rises", e <= e_prev + kEnergyRounding * std::max(e_prev, 1e-9));
    e_prev = std::min(e, e_prev);
  }
  check.check("within the work budget", !w.exhausted());
  if (s.run_s <= 0.0) check.check("at rest in time", w.atRest());
  if (w.atRest()) {
    for (const BallState& b : w.balls()) {
      check.check("none left in the air", b.pocket || (b.z == 0.0 && b.vz == 0.0),
                  "ball " + std::to_string(b.id));
    }
  }
  if (count) rep.simulated_s += w.time();
  mix(static_cast<double>(w.events().size()));
  return hash.value();
}

Scene sceneOf(const Scenario& s, EngineKind engine) {
  Scene scene;
  scene.table = s.table;
  scene.physics = s.physics;
  scene.step = s.step;
  scene.step.engine = engine;
  scene.balls = s.balls;
  scene.shot = s.shot;
  if (s.run_s > 0.0) scene.until = s.run_s;
  return scene;
}

// The reference engine has no steps to look between: its result is checked as a whole, with
// the same limits. Returns a fingerprint of the result, for the twin-run comparison.
std::uint64_t runReference(const Scenario& s, const StressOptions& o, StressReport& report,
                           bool count) {
  StressReport scratch;
  StressReport& rep = count ? report : scratch;
  Checker check(rep, "reference engine: " + s.name);
  const Scene scene = sceneOf(s, EngineKind::named("reference"));
  const SimResult r = simulate(scene);
  const double radius = s.physics.ball_radius;
  // The energy the run starts with, the cue strike included: the same strike as Box2D's.
  const std::unique_ptr<Engine> start_engine = makeEngine(s.table, s.physics, s.step);
  Engine& start = *start_engine;
  for (const BallState& b : s.balls) start.addBall(b);
  if (s.shot) start.strike(kCueBall, *s.shot);
  const double e_start = energy(start.balls(), radius, s.physics.ball_mass, s.physics.gravity);
  const auto fault = resultFault(scene, r);
  check.check("finite, and on the table or pocketed", !fault, fault.value_or(""));
  if (fault) return 0;
  const TableGeometry table = buildTable(s.table, radius);
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    const BallState& b = r.balls[i];
    if (b.pocket) {
      const bool announced = s.balls[i].pocket || announcedOff(b, r.events, 0);
      check.check("off the table with an event", announced, "ball " + std::to_string(b.id));
      continue;
    }
    check.check("not sunk into a cushion", cushionSink(table, b.pos, radius) <= kMaxSink,
                "ball " + std::to_string(b.id));
    for (std::size_t j = i + 1; j < r.balls.size(); ++j) {
      if (r.balls[j].pocket) continue;
      const double gap = centreDistance(b, r.balls[j]) - 2.0 * radius;
      check.check("no overlap", gap >= -kMaxOverlap,
                  "balls " + std::to_string(b.id) + "," + std::to_string(r.balls[j].id));
    }
  }
  const double e_end = energy(r.balls, radius, s.physics.ball_mass, s.physics.gravity);
  check.check("energy never rises", e_end <= e_start + kEnergyRounding * std::max(e_start, 1e-9));
  check.check("within the work budget", r.end != SimEnd::Budget);
  if (s.run_s <= 0.0) {
    check.check("at rest in time", r.end == SimEnd::Rest && r.time <= o.rest_within_s);
  }
  if (count) {
    ++rep.reference_runs;
    rep.simulated_s += r.time;
  }
  BitHash hash;
  hash.add(static_cast<std::int64_t>(stateHash(r.balls)));
  hash.add(static_cast<std::int64_t>(r.events.size()));
  hash.add(r.time);
  return hash.value();
}

// Random non-overlapping balls inside the table, some frozen to a cushion.
std::vector<BallState> randomLayout(std::uint64_t& rng, const TableGeometry& t, double r, int n) {
  std::vector<BallState> balls;
  const double hx = t.def.length / 2.0 - r, hy = t.def.width / 2.0 - r;
  for (int tries = 0; static_cast<int>(balls.size()) < n && tries < 10000; ++tries) {
    Vec2 p{uniform(rng, -hx, hx), uniform(rng, -hy, hy)};
    if (splitmix64(rng) % 5 == 0) p.y = splitmix64(rng) % 2 ? hy : -hy;  // frozen to a rail
    if (!t.ballFits(p, r)) continue;
    bool clear = true;
    for (const BallState& b : balls) clear &= length(b.pos - p) >= 2.0 * r;
    if (clear) balls.push_back(BallState::at(static_cast<int>(balls.size()), p));
  }
  return balls;
}

double logUniform(std::uint64_t& rng, double lo, double hi) {
  return lo * std::pow(hi / lo, uniform(rng, 0.0, 1.0));
}

// One of 0, 1 or anything between: the ends are where restitution breaks solvers.
double restitution(std::uint64_t& rng) {
  const auto pick = splitmix64(rng) % 3;
  return pick == 0 ? 0.0 : pick == 1 ? 1.0 : uniform(rng, 0.0, 1.0);
}

// A custom table anywhere in the allowed range: from the smallest that keeps a ball's
// diameter of rail between every two pockets to ten metres, with mouths from narrower than
// a ball (pockets nothing can enter) to six radii.
TableDef drawTable(std::uint64_t& rng, double r) {
  if (splitmix64(rng) % 4 == 0) {
    const TableDef named[] = {TableDef::nineFoot(), TableDef::eightFoot(), TableDef::sevenFoot()};
    return named[splitmix64(rng) % 3];
  }
  TableDef t;
  t.corner_pocket = uniform(rng, 1.5 * r, 6.0 * r);
  t.side_pocket = uniform(rng, 1.5 * r, 6.0 * r);
  t.corner_jaw_deg = uniform(rng, 91.0, 179.0);
  t.side_jaw_deg = uniform(rng, 91.0, 179.0);
  const double rail = 2.0 * r * limits::kMinRailInDiameters;
  const double c = t.corner_pocket / std::sqrt(2.0);
  const double min_width = 2.0 * c + rail;
  const double min_length = 2.0 * (c + t.side_pocket / 2.0 + rail);
  const double big = splitmix64(rng) % 4 == 0 ? limits::kMaxTableLength : 3.0;
  t.width = std::min(logUniform(rng, min_width, std::max(min_width, big / 2.0)), 5.0) * 1.000001;
  t.length = std::max(t.width, min_length) * logUniform(rng, 1.000001, 3.0);
  t.length = std::min(t.length, limits::kMaxTableLength);
  t.width = std::min(t.width, t.length);
  return t;
}

TableDef randomTable(std::uint64_t& rng, double r) {
  // Drawn again until the table is one the input allows.
  for (int tries = 0; tries < 100; ++tries) {
    TableDef t = drawTable(rng, r);
    if (!checkTable(t, r)) return t;
  }
  return TableDef::nineFoot();
}

PhysicsParams randomPhysics(std::uint64_t& rng) {
  PhysicsParams p;
  p.cloth = static_cast<ClothModel>(splitmix64(rng) % 3);
  p.ball_radius = splitmix64(rng) % 2
                      ? PhysicsParams{}.ball_radius
                      : logUniform(rng, limits::kMinBallRadius, limits::kMaxBallRadius);
  p.ball_mass = logUniform(rng, limits::kMinBallMass, limits::kMaxBallMass);
  p.ball_restitution = restitution(rng);
  p.cushion_restitution = restitution(rng);
  const bool frictionless = splitmix64(rng) % 3 == 0;
  p.rolling_friction = frictionless ? 0.0 : uniform(rng, 0.0, 0.05);
  p.sliding_friction = frictionless ? 0.0 : uniform(rng, 0.0, 0.5);
  p.cushion_friction = frictionless ? 0.0 : uniform(rng, 0.0, 0.5);
  p.spin_decay = frictionless ? 0.0 : uniform(rng, 0.0, 20.0);
  p.linear_damping = frictionless ? 0.0 : uniform(rng, 0.0, 1.0);
  // The models are drawn from a copy, so that every scene drawn before they existed stays.
  std::uint64_t models = rng ^ 0x6d6f64656c73ULL;
  const auto ball_ball = BallBallModel::names();
  p.ball_ball = BallBallModel::named(ball_ball[splitmix64(models) % ball_ball.size()]);
  const std::vector<std::string> cushions = CushionModel::names();
  p.cushion = CushionModel::named(cushions[splitmix64(models) % cushions.size()]);
  // The nose anywhere strictly between the ball's centre and its top.
  p.cushion_height = p.ball_radius * uniform(models, 1.001, 1.999);
  p.ball_friction.a = uniform(models, 0.0, 0.1);
  // The contact orders and the speed-dependent cushion's curve from a copy of their own, for
  // the same reason.
  std::uint64_t orders = rng ^ 0x6f7264657273ULL;
  p.frozen = splitmix64(orders) % 2 ? ContactOrder::Simultaneous : ContactOrder::Sequential;
  p.corner = splitmix64(orders) % 2 ? ContactOrder::Simultaneous : ContactOrder::Sequential;
  p.cushion_contact_time = uniform(orders, 0.0, limits::kMaxCushionContactTime);
  p.cushion_restitution_base = uniform(orders, 0.0, 1.0);
  p.cushion_restitution_slope =
      uniform(orders, -limits::kMaxRestitutionSlope, limits::kMaxRestitutionSlope);
  p.cushion_restitution_quadratic =
      uniform(orders, -limits::kMaxRestitutionQuadratic, limits::kMaxRestitutionQuadratic);
  p.cushion_restitution_min = uniform(orders, 0.0, 1.0);
  // The pocket model and its back's restitution, from a copy of their own as well.
  std::uint64_t pockets = rng ^ 0x706f636b657473ULL;
  p.pocket = splitmix64(pockets) % 2 ? PocketModel::Fall : PocketModel::Drop;
  p.pocket_restitution = uniform(pockets, 0.0, 1.0);
  return p;
}

StepParams randomStep(std::uint64_t& rng, double r) {
  StepParams s;
  s.box2d.scale =
      logUniform(rng, std::max(limits::kMinScale, limits::kMinBallUnits / r), limits::kMaxScale);
  s.hz = logUniform(rng, limits::kMinHz, limits::kMaxHz);
  return s;
}

// Sets every ball moving at up to the top speed, with spin up to the top surface speed.
void setMoving(std::uint64_t& rng, std::vector<BallState>& balls, const PhysicsParams& p,
               bool varied_mass) {
  const double w_max = limits::kMaxSurfaceSpeed / p.ball_radius / std::sqrt(3.0);
  for (BallState& b : balls) {
    b.vel = fromAngle(uniform(rng, -kPi, kPi)) * uniform(rng, 0.0, limits::kMaxSpeed);
    if (p.spin()) {
      b.w = {uniform(rng, -w_max, w_max), uniform(rng, -w_max, w_max), uniform(rng, -w_max, w_max)};
    }
    if (varied_mass) b.mass = logUniform(rng, limits::kMinBallMass, limits::kMaxBallMass);
  }
}

// Balls packed round one jaw of a pocket (on a table without pockets, into a corner), as close
// to it and to each other as they fit.
std::vector<BallState> crowdAtJaw(std::uint64_t& rng, const TableGeometry& t, double r, int n) {
  Vec2 jaw;
  if (t.pockets.empty()) {
    jaw = t.cushion_loop[splitmix64(rng) % t.cushion_loop.size()];
  } else {
    const Pocket& pk = t.pockets[splitmix64(rng) % t.pockets.size()];
    jaw = splitmix64(rng) % 2 ? pk.jaw_a : pk.jaw_b;
  }
  std::vector<BallState> balls;
  for (int tries = 0; static_cast<int>(balls.size()) < n && tries < 20000; ++tries) {
    const double reach = r * (1.0 + 0.5 * std::sqrt(static_cast<double>(tries)));
    Vec2 p = jaw + fromAngle(uniform(rng, -kPi, kPi)) * uniform(rng, r, reach);
    if (!t.ballFits(p, r)) continue;
    bool clear = true;
    for (const BallState& b : balls) clear &= length(b.pos - p) >= 2.0 * r;
    if (clear) balls.push_back(BallState::at(static_cast<int>(balls.size()), p));
  }
  return balls;
}

// Balls packed round a knuckle of a rounded jaw, as close to it and to each other as they fit.
std::vector<BallState> crowdAtKnuckle(std::uint64_t& rng, const TableGeometry& t, double r, int n) {
  const CushionArc& arc = t.arcs[splitmix64(rng) % t.arcs.size()];
  std::vector<BallState> balls;
  for (int tries = 0; static_cast<int>(balls.size()) < n && tries < 20000; ++tries) {
    const double reach = r * (1.0 + 0.5 * std::sqrt(static_cast<double>(tries)));
    Vec2 p =
        arc.centre + fromAngle(uniform(rng, -kPi, kPi)) * (arc.radius + uniform(rng, r, reach));
    if (!t.ballFits(p, r)) continue;
    bool clear = true;
    for (const BallState& b : balls) clear &= length(b.pos - p) >= 2.0 * r;
    if (clear) balls.push_back(BallState::at(static_cast<int>(balls.size()), p));
  }
  return balls;
}

// Everything the input allows, drawn at random: table, physics, step and balls.
Scenario randomSettings(std::uint64_t& rng, int i, bool at_jaw, bool pocketless = false) {
  Scenario s;
  s.kind =
      std::string(at_jaw ? "crowd against a jaw" : "random settings") + (pocketless ? ", no pockets"
                                                                         : at_jaw ? ", any settings"
                                                                                  : "");
  s.name = std::string(pocketless ? "no-pocket " : "") + (at_jaw ? "jaw #" : "settings #") +
           std::to_string(i);
  s.physics = randomPhysics(rng);
  const double r = s.physics.ball_radius;
  s.table = randomTable(rng, r);
  // Carom's four straight cushions (and their square corners) on the same table sizes.
  if (pocketless) s.table.pockets = false;
  s.step = randomStep(rng, r);
  const TableGeometry t = buildTable(s.table, r);
  const int n = 2 + static_cast<int>(splitmix64(rng) % (at_jaw ? 12 : 20));
  s.balls = at_jaw ? crowdAtJaw(rng, t, r, n) : randomLayout(rng, t, r, n);
  if (at_jaw) {
    Shot shot = Shot::withSpeed(uniform(rng, -180.0, 180.0), limits::kMaxSpeed);
    if (s.balls.size() > 1) {
      const Vec2 to = s.balls[1].pos - s.balls[0].pos;
      shot = Shot::withSpeed(radToDeg(std::atan2(to.y, to.x)), limits::kMaxSpeed);
    }
    s.shot = shot;
  } else {
    setMoving(rng, s.balls, s.physics, splitmix64(rng) % 2 == 0);
  }
  // A cloth that stops the balls well within the rest limit is run to rest; any other runs for
  // a fixed time. A kiss can double a speed, hence the factor 2.
  const PhysicsParams& p = s.physics;
  const double v = 2.0 * limits::kMaxSpeed;
  const double to_rest = p.cloth == ClothModel::Damping
                             ? std::log(v / p.rest_speed) / std::max(p.linear_damping, 1e-9)
                             : v / std::max(p.rolling_friction * p.gravity, 1e-9);
  s.run_s = to_rest < 30.0 ? 0.0 : 2.0;
  std::ostringstream about;
  about << " (" << clothModelName(p.cloth) << " cloth, R " << p.ball_radius << ", e "
        << p.ball_restitution << "/" << p.cushion_restitution << ", table " << s.table.length << "x"
        << s.table.width << " mouths " << s.table.corner_pocket << "/" << s.table.side_pocket
        << ", k " << s.step.box2d.scale << ", " << s.step.hz << " Hz)";
  s.name += about.str();
  s.fixed_step = true;
  return s;
}

std::vector<Scenario> scenarios(const StressOptions& o) {
  std::vector<Scenario> out;
  std::uint64_t rng = o.seed;
  const PhysicsParams real = PhysicsParams::real();
  const double r = real.ball_radius;
  const TableGeometry table = buildTable(TableDef{}, r);
  for (int i = 0; i < o.random_layouts; ++i) {
    Scenario s;
    s.kind = "random layout and shot";
    s.name = "random #" + std::to_string(i);
    s.balls = randomLayout(rng, table, r, 2 + static_cast<int>(splitmix64(rng) % 15));
    Shot shot = Shot::withSpeed(uniform(rng, -180.0, 180.0), uniform(rng, 0.001, 13.0));
    const double tip_r = 0.5 * std::sqrt(uniform(rng, 0.0, 1.0)), tip_a = uniform(rng, 0.0, 6.283);
    shot.tip = fromAngle(tip_a) * tip_r;
    s.shot = shot;
    out.push_back(s);
  }
  std::uint64_t settings_rng = o.seed ^ 0x5E771465ULL;
  for (int i = 0; i < o.random_settings; ++i) {
    out.push_back(randomSettings(settings_rng, i, i % 3 == 2));
  }

  // Three-cushion: the carom tables and equipment, three balls, any stroke.
  std::uint64_t carom_rng = o.seed ^ 0xCA20ULL;
  for (int i = 0; i < o.random_layouts / 4; ++i) {
    Scenario s;
    s.kind = "carom table and equipment";
    s.physics = PhysicsParams::carom();
    s.table = i % 2 ? TableDef::caromSmall() : TableDef::carom();
    s.name = std::string(i % 2 ? "carom-small" : "carom") + " #" + std::to_string(i);
    const TableGeometry carom_table = buildTable(s.table, s.physics.ball_radius);
    s.balls = randomLayout(carom_rng, carom_table, s.physics.ball_radius, 3);
    Shot shot = Shot::withSpeed(uniform(carom_rng, -180.0, 180.0),
                                uniform(carom_rng, 0.5, limits::kMaxSpeed));
    const double tip_r = 0.5 * std::sqrt(uniform(carom_rng, 0.0, 1.0));
    shot.tip = fromAngle(uniform(carom_rng, 0.0, 6.283)) * tip_r;
    shot.elevation_rad = splitmix64(carom_rng) % 4 == 0 ? uniform(carom_rng, 0.0, 1.0) : 0.0;
    s.shot = shot;
    out.push_back(s);
  }
  // Snooker: the snooker tables (rounded jaws) and equipment, up to 22 balls, any stroke; one
  // scene in three crowds the balls round a knuckle.
  std::uint64_t snooker_rng = o.seed ^ 0x5A00CE2ULL;
  for (int i = 0; i < o.random_layouts / 4; ++i) {
    Scenario s;
    s.kind = "snooker table and equipment";
    s.physics = PhysicsParams::snooker();
    s.table = i % 2 ? TableDef::snookerTenFoot() : TableDef::snooker();
    s.name = std::string(i % 2 ? "snooker-10ft" : "snooker") + " #" + std::to_string(i);
    const double sr = s.physics.ball_radius;
    const TableGeometry snooker_table = buildTable(s.table, sr);
    const int n = 2 + static_cast<int>(splitmix64(snooker_rng) % 21);
    if (i % 3 == 2) {
      s.kind += ", crowd against a knuckle";
      s.balls = crowdAtKnuckle(snooker_rng, snooker_table, sr, n);
      // Its own (pairwise) contacts, as the crowds against a jaw keep theirs: Box2D's own ball
      // solver jams in a crowd at a jaw, sharp or rounded (this layout on sharp jaws, too,
      // stops at the work budget with "contacts": "box2d").
      s.fixed_step = true;
    } else {
      s.balls = randomLayout(snooker_rng, snooker_table, sr, n);
    }
    Shot shot = Shot::withSpeed(uniform(snooker_rng, -180.0, 180.0),
                                uniform(snooker_rng, 0.5, limits::kMaxSpeed));
    shot.tip = fromAngle(uniform(snooker_rng, 0.0, 6.283)) *
               (0.5 * std::sqrt(uniform(snooker_rng, 0.0, 1.0)));
    s.shot = shot;
    out.push_back(s);
  }
  {
    Scenario s;
    s.kind = "crowded table";
    s.name = std::to_string(o.crowded_balls) + " balls";
    std::uint64_t crowd_rng = o.seed ^ 0xC0FFEEULL;
    s.balls = randomLayout(crowd_rng, table, r, o.crowded_balls);
    s.shot = Shot::withSpeed(10.0, 13.0);
    s.shot->tip = {0.2, -0.3};
    out.push_back(s);
  }
  {
    Scenario s;
    s.kind = "frozen balls";
    s.name = "a row frozen to the top rail, hit along it";
    const double y = table.def.width / 2.0 - r;
    s.balls.push_back(BallState::at(0, {-0.9, y}));
    for (int i = 1; i <= 6; ++i) s.balls.push_back(BallState::at(i, {-0.5 + 2.0 * r * (i - 1), y}));
    s.shot = Shot::withSpeed(0.0, 8.0);
    out.push_back(s);
    s.name = "a frozen cluster in a corner, hit hard";
    s.balls = {BallState::at(0, {0.0, 0.0})};
    const Vec2 corner{table.def.length / 2.0 - r, table.def.width / 2.0 - r - 0.1};
    for (int i = 0; i < 4; ++i) {
      s.balls.push_back(BallState::at(1 + i, corner - Vec2{2.0 * r * i, 0.0}));
      s.balls.push_back(BallState::at(5 + i, corner - Vec2{2.0 * r * i + r, std::sqrt(3.0) * r}));
    }
    s.shot = Shot::withSpeed(radToDeg(std::atan2(corner.y, corner.x)), 13.0);
    out.push_back(s);
  }
  {
    Scenario s;
    s.kind = "ball in a jaw";
    s.name = "a ball resting in the top-side pocket's mouth, then hit";
    const Pocket& side = table.pockets[1];
    // Just inside the mouth, touching the jaw point but short of the drop circle.
    Vec2 p = side.jaw_a + Vec2{r * 0.8, -r * 0.6};
    for (int k = 0; k < 200 && !table.ballFits(p, r); ++k) p.y -= 0.0005;
    s.balls = {BallState::at(0, {-0.4, 0.2}), BallState::at(1, p)};
    s.shot = Shot::withSpeed(radToDeg(std::atan2(p.y - 0.2, p.x + 0.4)), 1.0);
    out.push_back(s);
  }
  {
    Scenario s;
    s.kind = "creeping balls";
    s.name = "balls at 1 mm/s";
    s.balls = {BallState::at(0, {0.0, 0.0}, {0.001, 0.0}),
               BallState::at(1, {2.0 * r + 1e-5, 0.0}, {-0.001, 0.0}),
               BallState::at(2, {0.3, table.def.width / 2.0 - r - 1e-5}, {0.0, 0.001})};
    out.push_back(s);
  }
  {
    Scenario s;
    s.kind = "endless run";
    s.name = "frictionless rack, e = 1, for " + std::to_string(o.long_run_s) + " s";
    s.physics.cloth = ClothModel::Friction;
    s.physics.rolling_friction = 0.0;
    s.physics.ball_restitution = 1.0;
    s.physics.cushion_restitution = 1.0;
    s.balls = breakScene().balls;
    s.shot = Shot::withSpeed(1.0, 6.0);
    s.run_s = o.long_run_s;
    out.push_back(s);
  }
  return out;
}

}  // namespace

long StressReport::failureCount() const {
  long n = 0;
  for (const auto& [what, count] : failures) n += count;
  return n;
}

std::optional<Scene> stressScene(const StressOptions& options, const std::string& name) {
  for (const Scenario& s : scenarios(options)) {
    if (s.name.rfind(name, 0) != 0) continue;
    Scenario chosen = s;
    if (!s.fixed_step) chosen.step = options.step;
    return sceneOf(chosen, options.step.engine);
  }
  return std::nullopt;
}

StressReport runStress(const StressOptions& options) {
  StressReport report;
  auto wanted = [&](const std::string& name) {
    return options.only.empty() ||
           std::any_of(options.only.begin(), options.only.end(),
                       [&](const std::string& prefix) { return name.rfind(prefix, 0) == 0; });
  };
  for (Scenario s : scenarios(options)) {
    if (!wanted(s.name)) continue;
    if (!s.fixed_step) s.step = options.step;
    ++report.scenarios[s.kind];
    const std::uint64_t first = runOnce(s, options, report, true);
    const std::uint64_t second = runOnce(s, options, report, false);
    Checker(report, s.name).check("two runs identical", first == second);
    if (!options.reference) continue;
    const std::uint64_t ref_first = runReference(s, options, report, true);
    const std::uint64_t ref_second = runReference(s, options, report, false);
    Checker(report, "reference engine: " + s.name)
        .check("two runs identical", ref_first == ref_second);
  }
  return report;
}

}  // namespace nineball
