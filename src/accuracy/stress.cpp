#include "nineball/stress.hpp"

#include <cmath>
#include <cstring>
#include <functional>
#include <sstream>

#include "nineball/random.hpp"
#include "nineball/scenes.hpp"
#include "nineball/world.hpp"

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
  double run_s = 0.0;  // 0: until rest (must come within rest_within_s)
};

double energy(const std::vector<BallState>& balls, double r, double mass) {
  double e = 0.0;
  for (const BallState& b : balls) {
    if (b.pocket) continue;
    const double m = b.mass.value_or(mass);
    e += 0.5 * m * dot(b.vel, b.vel) +
         0.2 * m * r * r * (b.w.x * b.w.x + b.w.y * b.w.y + b.w.z * b.w.z);
  }
  return e;
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
    if (report_.first_failures.size() < kFailuresKept) {
      report_.first_failures.push_back(name_ + ": " + what + (detail.empty() ? "" : " " + detail));
    }
  }

 private:
  StressReport& report_;
  std::string name_;
};

// One run; returns a fingerprint of everything it produced, for the twin-run comparison.
std::uint64_t runOnce(const Scenario& s, const StressOptions& o, StressReport& report, bool count) {
  StressReport scratch;
  StressReport& rep = count ? report : scratch;
  Checker check(rep, s.name);
  World w(s.table, s.physics, s.step);
  for (const BallState& b : s.balls) w.addBall(b);
  if (s.shot) w.strike(kCueBall, *s.shot);
  const double r = s.physics.ball_radius;
  double e_prev = energy(w.balls(), r, s.physics.ball_mass);
  std::uint64_t hash = 1469598103934665603ULL;
  auto mix = [&hash](double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    hash = (hash ^ bits) * 1099511628211ULL;
  };
  const double limit = s.run_s > 0.0 ? s.run_s : o.rest_within_s;
  std::size_t events_seen = 0;
  std::vector<bool> was_pocketed(s.balls.size(), false);
  while (w.time() < limit && (s.run_s > 0.0 || !w.atRest())) {
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
          bool announced = false;
          for (std::size_t k = events_seen; k < events.size(); ++k) {
            announced |= events[k].type == EventType::Pocket && events[k].a == b.id;
          }
          check.check("pocketed with an event", announced, "ball " + std::to_string(b.id));
          was_pocketed[i] = true;
        }
        continue;
      }
      check.check("inside the cushions", w.table().insideLoop(b.pos),
                  "ball " + std::to_string(b.id));
      check.check("not sunk into a cushion", cushionSink(w.table(), b.pos, r) <= kMaxSink,
                  "ball " + std::to_string(b.id));
      for (std::size_t j = i + 1; j < balls.size(); ++j) {
        if (balls[j].pocket) continue;
        const double gap = length(balls[j].pos - b.pos) - 2.0 * r;
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
    const double e = energy(balls, r, s.physics.ball_mass);
    check.check("energy never rises", e <= e_prev + kEnergyRounding * std::max(e_prev, 1e-9));
    e_prev = std::min(e, e_prev);
  }
  if (s.run_s <= 0.0) check.check("at rest in time", w.atRest());
  if (count) rep.simulated_s += w.time();
  mix(static_cast<double>(w.events().size()));
  return hash;
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

double cushionSink(const TableGeometry& t, Vec2 c, double r) {
  double sink = 0.0;
  const auto& loop = t.cushion_loop;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
    const Vec2 ab = b - a;
    const double u = std::clamp(dot(c - a, ab) / dot(ab, ab), 0.0, 1.0);
    sink = std::max(sink, r - length(c - (a + ab * u)));
  }
  return sink;
}

long StressReport::failureCount() const {
  long n = 0;
  for (const auto& [what, count] : failures) n += count;
  return n;
}

StressReport runStress(const StressOptions& options) {
  StressReport report;
  for (Scenario s : scenarios(options)) {
    s.step = options.step;
    ++report.scenarios[s.kind];
    const std::uint64_t first = runOnce(s, options, report, true);
    const std::uint64_t second = runOnce(s, options, report, false);
    Checker(report, s.name).check("two runs identical", first == second);
  }
  return report;
}

}  // namespace nineball
