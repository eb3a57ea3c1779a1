// The stroke model's execution noise (executeStroke, cueingNamed): the tournaments' Gaussian as
// FastFiz draws it, five times it, and a level's own errors drawn exactly as before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "nineball/planner.hpp"
#include "nineball/random.hpp"

using nineball::degToRad;
using nineball::PhysicsParams;
using nineball::radToDeg;
using nineball::Shot;
using nineball::Vec2;
using nineball::ai::allLevels;
using nineball::ai::cueingNamed;
using nineball::ai::cueingNames;
using nineball::ai::executeStroke;
using nineball::ai::ExecutionNoise;
using nineball::ai::Level;
using nineball::ai::levelName;
using nineball::ai::LevelSettings;
using nineball::ai::Plan;
using nineball::ai::Planner;
using nineball::ai::ShotKind;
using nineball::ai::StrokeDifficulty;

namespace {

// Draws per measured deviation. A sample standard deviation of n Gaussian draws errs by about
// sd / sqrt(2 n), 0.5 % here: the 3 % tolerances below are six of those, so a right model
// passes whatever the seed, while the deviations swapped back (0.1 for 0.125 degree of aim,
// 20 % off) or the speed's error put on the ball (0.075 for 0.117 m/s) miss by forty or more.
constexpr int kDraws = 20000;
constexpr double kTolerance = 0.03;

// FastFiz's cue, 600 g (Table::CUE_MASS in fastfiz/include/FastFiz.h).
constexpr double kFastFizCueMass = 0.600;

// FastFiz's stroke in its own terms (CueStrikeEvent; Leckie and Greenspan's eq. 1): the cue
// ball's speed per m/s of the stick's, the tip meeting the ball at a (across) and b (up) in the
// table's frame, c = sqrt(R^2 - a^2 - b^2) behind its centre, the cue elevated by t.
double fastFizBallPerStick(double a, double b, double t, double radius, double mass) {
  const double c = std::sqrt(radius * radius - a * a - b * b);
  const double co = std::cos(t), si = std::sin(t);
  const double bracket = a * a + b * b * co * co + c * c * si * si - 2.0 * b * c * co * si;
  return 2.0 / (1.0 + mass / kFastFizCueMass + 5.0 / (2.0 * radius * radius) * bracket);
}

// The same for nineball's tip, which is seen along the cue: the point it meets is `side` across
// and height cos t + depth sin t up in the table's frame (cue.cpp's contact point).
double fastFizBallPerStick(Vec2 tip, double elevation_rad) {
  const PhysicsParams p;
  const double depth = std::sqrt(1.0 - tip.x * tip.x - tip.y * tip.y);
  const double up = tip.y * std::cos(elevation_rad) + depth * std::sin(elevation_rad);
  return fastFizBallPerStick(tip.x * p.ball_radius, up * p.ball_radius, elevation_rad,
                             p.ball_radius, p.ball_mass);
}

// Standard deviations of what a stroke changes, measured over kDraws executions.
struct Spread {
  double aim_deg = 0, elevation_deg = 0, tip_x_m = 0, tip_y_m = 0, speed = 0, mean_speed = 0;
};

Spread measure(const Shot& intended, const LevelSettings& s, const StrokeDifficulty& d,
               std::uint64_t seed) {
  const double r = PhysicsParams{}.ball_radius;
  std::uint64_t rng = seed;
  double aim = 0, elevation = 0, tip_x = 0, tip_y = 0, speed = 0, speed_sq = 0;
  for (int k = 0; k < kDraws; ++k) {
    const Shot shot = executeStroke(intended, s, d, PhysicsParams{}, rng);
    const auto sq = [](double v) { return v * v; };
    aim += sq(radToDeg(shot.heading_rad - intended.heading_rad));
    elevation += sq(radToDeg(shot.elevation_rad - intended.elevation_rad));
    tip_x += sq((shot.tip.x - intended.tip.x) * r);
    tip_y += sq((shot.tip.y - intended.tip.y) * r);
    speed += shot.speed;
    speed_sq += shot.speed * shot.speed;
  }
  Spread out;
  out.aim_deg = std::sqrt(aim / kDraws);
  out.elevation_deg = std::sqrt(elevation / kDraws);
  out.tip_x_m = std::sqrt(tip_x / kDraws);
  out.tip_y_m = std::sqrt(tip_y / kDraws);
  out.mean_speed = speed / kDraws;
  out.speed = std::sqrt(speed_sq / kDraws - out.mean_speed * out.mean_speed);
  return out;
}

void expectWithin(double measured, double expected, const char* what) {
  EXPECT_NEAR(measured, expected, kTolerance * expected) << what;
}

Shot intendedShot() {
  Shot shot = Shot::withSpeed(30.0, 3.0);
  shot.elevation_rad = degToRad(10.0);
  return shot;
}

// A hard stroke: under the tournaments' noise it errs no more than an easy one.
constexpr StrokeDifficulty kHardCut{60.0, 1.5, false, false};

// The stroke as Planner::execute drew a level's errors before executeStroke: the reference a
// level's draws are held to, bit for bit (every match and golden replays them).
Shot levelStrokeAsBefore(Shot shot, const LevelSettings& s, const StrokeDifficulty& d,
                         std::uint64_t& rng) {
  const double scale = d.is_break ? 1.0 / 3.0 : 1.0;
  const double sin_cut = std::sin(degToRad(d.cut_deg));
  const double pace = std::max(0.0, shot.speed / nineball::ai::kPaceReference - 1.0);
  const double growth = d.is_break
                            ? 1.0
                            : (1.0 + s.cut_growth * sin_cut * sin_cut) *
                                  (1.0 + s.reach_growth * d.reach_m) * (1.0 + s.pace_growth * pace);
  const double aim_error = nineball::gaussian(rng);
  const double speed_error = nineball::gaussian(rng);
  shot.heading_rad += scale * growth * degToRad(s.aim_noise_deg) * aim_error;
  shot.speed = std::clamp(shot.speed * (1.0 + scale * s.speed_noise * speed_error), 0.05, 13.0);
  const double elevation_sd = d.is_jump ? s.jump_elevation_noise_deg : s.elevation_noise_deg;
  if (elevation_sd > 0.0) {
    const double e = shot.elevation_rad + scale * degToRad(elevation_sd) * nineball::gaussian(rng);
    shot.elevation_rad = std::clamp(e, 0.0, degToRad(60.0));
  }
  if (s.tip_noise_m > 0.0) {
    const double k = scale * s.tip_noise_m / PhysicsParams{}.ball_radius;
    shot.tip.x += k * nineball::gaussian(rng);
    shot.tip.y += k * nineball::gaussian(rng);
  }
  return shot;
}

}  // namespace

TEST(PlannerStroke, TheOlympiadIsFastFizsGaussian) {
  // FastFiz's GaussianNoise (Noise.h): 0.125 degree of aim (phi), 0.1 degree of elevation
  // (theta), 0.5 mm of each tip offset (a, b), on a hard cut as on any stroke; and 0.075 m/s on
  // the stick, which a centred tip turns into 2 / (1 + m/M) times that on the ball.
  const Spread s = measure(intendedShot(), *cueingNamed("olympiad"), kHardCut, 7);
  expectWithin(s.aim_deg, 0.125, "aim");
  expectWithin(s.elevation_deg, 0.1, "elevation");
  expectWithin(s.tip_x_m, 0.0005, "tip across");
  expectWithin(s.tip_y_m, 0.0005, "tip up");
  const double ball_sd = 0.075 * fastFizBallPerStick({0.0, 0.0}, degToRad(10.0));
  EXPECT_NEAR(ball_sd, 0.117, 0.001);  // 1.56 x the stick's with a 170 g ball and a 600 g cue
  expectWithin(s.speed, ball_sd, "speed");
  EXPECT_NEAR(s.mean_speed, 3.0, 0.01);  // no bias beyond the tip's second-order one
}

TEST(PlannerStroke, TheStickSpeedErrorReachesTheBallAsFastFizStrikes) {
  // Only the stick's speed errs: the ball's deviation is FastFiz's v / V times 0.075 m/s, its
  // formula evaluated in its own frame, for a centred, an off-centre and an elevated stroke.
  LevelSettings only_speed;
  only_speed.speed_noise_ms = 0.075;
  for (const auto& [tip, elevation_deg] : std::vector<std::pair<Vec2, double>>{
           {{0.0, 0.0}, 0.0}, {{0.4, -0.3}, 0.0}, {{0.4, -0.3}, 30.0}, {{0.0, 0.35}, 50.0}}) {
    Shot shot = intendedShot();
    shot.tip = tip;
    shot.elevation_rad = degToRad(elevation_deg);
    const Spread s = measure(shot, only_speed, {}, 11);
    const double ratio = fastFizBallPerStick(tip, shot.elevation_rad);
    expectWithin(s.speed, 0.075 * ratio, "speed");
    EXPECT_NEAR(s.mean_speed, 3.0, 0.005);
  }
  // The tip struck, not the tip meant, sets the ball's speed: off centre it is slower.
  Shot centred = intendedShot();
  LevelSettings tip_only;
  tip_only.speed_noise_ms = 1e-12;  // the stick's speed kept, the stroke through the stick
  tip_only.tip_noise_m = 0.005;
  std::uint64_t rng = 3;
  const Shot struck = executeStroke(centred, tip_only, {}, PhysicsParams{}, rng);
  const double expected = 3.0 / fastFizBallPerStick({0.0, 0.0}, centred.elevation_rad) *
                          fastFizBallPerStick(struck.tip, centred.elevation_rad);
  EXPECT_NEAR(struck.speed, expected, 1e-9);
  EXPECT_LT(struck.speed, 3.0);
}

TEST(PlannerStroke, OlympiadFiveTimesIsFiveTimesEachDeviation) {
  const ExecutionNoise one = ExecutionNoise::olympiad();
  const ExecutionNoise five = *ExecutionNoise::named("olympiad-5x");
  EXPECT_DOUBLE_EQ(five.aim_deg, 5.0 * one.aim_deg);
  EXPECT_DOUBLE_EQ(five.elevation_deg, 5.0 * one.elevation_deg);
  EXPECT_DOUBLE_EQ(five.speed_ms, 5.0 * one.speed_ms);
  EXPECT_DOUBLE_EQ(five.tip_m, 5.0 * one.tip_m);
  const Spread s = measure(intendedShot(), *cueingNamed("olympiad-5x"), kHardCut, 5);
  expectWithin(s.aim_deg, 0.625, "aim");
  expectWithin(s.elevation_deg, 0.5, "elevation");
  expectWithin(s.tip_x_m, 0.0025, "tip across");
  expectWithin(s.tip_y_m, 0.0025, "tip up");
}

TEST(PlannerStroke, EveryNameHasItsCueing) {
  std::vector<std::string> expected;
  for (Level level : allLevels()) expected.emplace_back(levelName(level));
  for (const char* name : {"none", "olympiad", "olympiad-5x"}) expected.emplace_back(name);
  EXPECT_EQ(cueingNames(), expected);
  EXPECT_EQ(ExecutionNoise::names(), (std::vector<std::string>{"none", "olympiad", "olympiad-5x"}));
  for (Level level : allLevels()) {
    const auto s = cueingNamed(levelName(level));
    ASSERT_TRUE(s) << levelName(level);
    const LevelSettings own = LevelSettings::of(level);
    EXPECT_EQ(s->aim_noise_deg, own.aim_noise_deg) << levelName(level);
    EXPECT_EQ(s->cut_growth, own.cut_growth) << levelName(level);
    EXPECT_EQ(s->speed_noise, own.speed_noise) << levelName(level);
    EXPECT_EQ(s->tip_noise_m, own.tip_noise_m) << levelName(level);
    EXPECT_EQ(s->jump_elevation_noise_deg, own.jump_elevation_noise_deg) << levelName(level);
    EXPECT_FALSE(s->noise_on_break) << levelName(level);
  }
  const auto none = cueingNamed("none");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->aim_noise_deg, 0.0);
  EXPECT_EQ(none->speed_noise_ms, 0.0);
  for (const auto& [name, k] :
       std::vector<std::pair<std::string, double>>{{"olympiad", 1.0}, {"olympiad-5x", 5.0}}) {
    const auto s = cueingNamed(name);
    ASSERT_TRUE(s) << name;
    EXPECT_DOUBLE_EQ(s->aim_noise_deg, 0.125 * k) << name;
    EXPECT_DOUBLE_EQ(s->elevation_noise_deg, 0.1 * k) << name;
    EXPECT_DOUBLE_EQ(s->jump_elevation_noise_deg, 0.1 * k) << name;
    EXPECT_DOUBLE_EQ(s->speed_noise_ms, 0.075 * k) << name;
    EXPECT_DOUBLE_EQ(s->tip_noise_m, 0.0005 * k) << name;
    EXPECT_EQ(s->cut_growth, 0.0) << name;
    EXPECT_EQ(s->speed_noise, 0.0) << name;
    EXPECT_TRUE(s->noise_on_break) << name;  // the break struck with the whole noise
  }
  for (const char* unknown : {"level", "loud", "hard", "Olympiad", ""}) {
    EXPECT_FALSE(cueingNamed(unknown)) << unknown;
  }
  // Struck with none, a stroke is as meant.
  std::uint64_t rng = 1;
  const Shot shot = executeStroke(intendedShot(), *none, kHardCut, PhysicsParams{}, rng);
  EXPECT_EQ(shot.heading_rad, intendedShot().heading_rad);
  EXPECT_EQ(shot.speed, intendedShot().speed);
  EXPECT_EQ(shot.elevation_rad, intendedShot().elevation_rad);
}

TEST(PlannerStroke, ALevelDrawsExactlyAsBefore) {
  // Every level, on a pot, a softened break and a jump, 300 strokes each from one generator:
  // the same bits as before executeStroke, and the generator left in the same state.
  for (Level level : allLevels()) {
    const LevelSettings s = LevelSettings::of(level);
    for (const StrokeDifficulty& d :
         {StrokeDifficulty{35.0, 0.8, false, false}, StrokeDifficulty{0.0, 0.0, true, false},
          StrokeDifficulty{10.0, 0.4, false, true}}) {
      std::uint64_t now = 42, before = 42;
      Shot shot = Shot::withSpeed(80.0, 4.5);
      shot.tip = {0.1, -0.2};
      shot.elevation_rad = d.is_jump ? degToRad(35.0) : 0.0;
      for (int k = 0; k < 300; ++k) {
        const Shot a = executeStroke(shot, s, d, PhysicsParams{}, now);
        const Shot b = levelStrokeAsBefore(shot, s, d, before);
        ASSERT_EQ(a.heading_rad, b.heading_rad) << levelName(level) << " " << k;
        ASSERT_EQ(a.speed, b.speed) << levelName(level) << " " << k;
        ASSERT_EQ(a.tip.x, b.tip.x) << levelName(level) << " " << k;
        ASSERT_EQ(a.tip.y, b.tip.y) << levelName(level) << " " << k;
        ASSERT_EQ(a.elevation_rad, b.elevation_rad) << levelName(level) << " " << k;
      }
      EXPECT_EQ(now, before) << levelName(level);
    }
  }
}

TEST(PlannerStroke, ThePlannerExecutesThroughExecuteStroke) {
  // Planner::execute is executeStroke with the plan's cut, reach and kind, from its seed.
  for (const ShotKind kind : {ShotKind::Pot, ShotKind::Break, ShotKind::Jump}) {
    Planner planner(Level::Master, ExecutionNoise::olympiad(), 7);
    Plan plan;
    plan.kind = kind;
    plan.cut_deg = 40.0;
    plan.reach_m = 0.9;
    plan.turn.shot = intendedShot();
    const StrokeDifficulty d{40.0, 0.9, kind == ShotKind::Break, kind == ShotKind::Jump};
    std::uint64_t rng = 7;
    for (int k = 0; k < 20; ++k) {
      const Shot a = planner.execute(plan).shot;
      const Shot b = executeStroke(plan.turn.shot, planner.settings(), d, PhysicsParams{}, rng);
      EXPECT_EQ(a.heading_rad, b.heading_rad);
      EXPECT_EQ(a.speed, b.speed);
      EXPECT_EQ(a.tip.x, b.tip.x);
      EXPECT_EQ(a.elevation_rad, b.elevation_rad);
    }
  }
}
