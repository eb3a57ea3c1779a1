// Balls in the air against their closed forms: the flight's time and apex, the bounces falling
// by the slate's restitution squared, the slate's friction never giving energy back, the
// stroke that drives the ball into the slate and jumps it, the scoop that is a miscue; in both
// engines, which follow the same arcs.
#include "physics/model/slate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include "nineball/engine.hpp"
#include "nineball/sim.hpp"
#include "physics/resolve/cue/cue.hpp"

namespace nineball::physics {
namespace {

constexpr double kPi = 3.14159265358979323846;
const char* const kEngineNames[] = {"reference", "box2d"};

std::unique_ptr<Engine> engineOf(const char* name, const PhysicsParams& p) {
  StepParams step;
  step.engine = EngineKind::named(name);
  TableDef table;
  return makeEngine(table, p, step);
}

std::vector<Event> eventsOf(const Engine& w, EventType type) {
  std::vector<Event> out;
  for (const Event& e : w.events()) {
    if (e.type == type) out.push_back(e);
  }
  return out;
}

TEST(Slate, AFlightLastsTwoVzOverGAndPeaksAtVzSquaredOverTwoG) {
  const PhysicsParams p = PhysicsParams::real();
  for (const double vz : {0.05, 0.4, 1.3, 3.0}) {
    Kinematics k;
    k.v = {0.7, -0.2};
    k.vz = vz;
    const Arc arc = beginArc(0.0, k, p);
    ASSERT_EQ(arc.phase, Phase::Airborne);
    const double flight = 2.0 * vz / p.gravity, apex = vz * vz / (2.0 * p.gravity);
    // Tolerance: a few roundings of the closed forms themselves.
    EXPECT_NEAR(arc.duration, flight, 1e-12 * flight) << vz;
    const Kinematics top = stateAt(arc, vz / p.gravity, p);
    EXPECT_NEAR(top.z, apex, 1e-12 * apex) << vz;
    EXPECT_NEAR(top.vz, 0.0, 1e-12) << vz;
    EXPECT_NEAR(top.p.x, 0.7 * vz / p.gravity, 1e-12);  // the flight carries the speed as it is
  }
  // From a height, falling: z0 = 0.1 m at rest lands after sqrt(2 z0 / g).
  Kinematics dropped;
  dropped.z = 0.1;
  EXPECT_NEAR(beginArc(0.0, dropped, p).duration, std::sqrt(0.2 / p.gravity), 1e-15);
}

TEST(Slate, BounceHeightsFallByTheRestitutionSquaredUntilTheLeastBounce) {
  PhysicsParams p = PhysicsParams::real();
  const double z0 = 0.2, e = p.table_restitution, g = p.gravity;
  for (const char* name : kEngineNames) {
    const auto w = engineOf(name, p);
    BallState b = BallState::at(1, {0.1, 0.1});
    b.z = z0;
    w->addBall(b);
    w->runUntilRest();
    const std::vector<Event> lands = eventsOf(*w, EventType::Land);
    // Bounce n lifts the ball e^2n z0; those under min_bounce_height are not flown.
    int bounces = 0;
    while (std::pow(e, 2 * (bounces + 1)) * z0 >= p.min_bounce_height) ++bounces;
    ASSERT_EQ(static_cast<int>(lands.size()), bounces + 1) << name;
    EXPECT_EQ(eventsOf(*w, EventType::Airborne).size(), static_cast<std::size_t>(bounces)) << name;
    double t = std::sqrt(2.0 * z0 / g);
    for (std::size_t n = 0; n < lands.size(); ++n) {
      EXPECT_NEAR(lands[n].t, t, 1e-12) << name << " landing " << n;
      // The flight after landing n rises e^(n+1) sqrt(2 g z0) and lasts twice its rise.
      t += 2.0 * std::pow(e, static_cast<double>(n + 1)) * std::sqrt(2.0 * g * z0) / g;
    }
    EXPECT_EQ(w->balls()[0].z, 0.0) << name;
    EXPECT_EQ(w->balls()[0].pos.x, 0.1) << name;  // straight down: it never moved across
  }
}

TEST(Slate, TheSlatesFrictionNeverGivesEnergyBack) {
  const PhysicsParams p = PhysicsParams::real();
  const double m = p.ball_mass, r = p.ball_radius, g = p.gravity;
  std::mt19937_64 rng(49);
  std::uniform_real_distribution<double> speed(-6.0, 6.0), spin(-300.0, 300.0), fall(-4.0, -0.01);
  int slips_ended = 0;
  for (int n = 0; n < 100000; ++n) {
    Kinematics k;
    k.v = {speed(rng), speed(rng)};
    k.w = {spin(rng), spin(rng), spin(rng)};
    k.vz = fall(rng);
    const Kinematics after = bounceOffSlate(k, p);
    const double before_j = mechanicalEnergy(k, m, r, g),
                 after_j = mechanicalEnergy(after, m, r, g);
    ASSERT_LE(after_j, before_j * (1.0 + 1e-14)) << n;
    ASSERT_GE(after.vz, 0.0);
    ASSERT_LE(after.vz, p.table_restitution * -k.vz * (1.0 + 1e-15));
    // The friction never reverses the slip: it ends it at most.
    const Vec2 u0 = slip(k.v, k.w, r), u1 = slip(after.v, after.w, r);
    ASSERT_GE(dot(u0, u1), -1e-12 * dot(u0, u0)) << n;
    if (length(u1) < 1e-9 * length(u0)) ++slips_ended;
  }
  std::printf("[ measured ] slate bounces: %d of 100000 ended the slip\n", slips_ended);
  EXPECT_GT(slips_ended, 0);
}

TEST(Slate, AnElevatedStrokeJumpsTheBallByTheSlatesRestitution) {
  const PhysicsParams p = PhysicsParams::real();
  Shot s = Shot::withSpeed(0.0, 4.0);
  s.elevation_rad = 30.0 * kPi / 180.0;
  // The cue drives the ball into the slate at V sin(theta); it comes back times e.
  const double vz = p.table_restitution * 4.0 * std::sin(s.elevation_rad);
  const double vx = 4.0 * std::cos(s.elevation_rad), flight = 2.0 * vz / p.gravity;
  std::vector<double> landed_x;
  for (const char* name : kEngineNames) {
    const auto w = engineOf(name, p);
    w->addBall(BallState::at(0, {-0.9, 0.0}));
    ASSERT_TRUE(w->strike(0, s)) << name;
    ASSERT_EQ(eventsOf(*w, EventType::Airborne).size(), 1u) << name;
    EXPECT_NEAR(w->balls()[0].vz, vz, 1e-12) << name;
    w->runFor(0.9 * flight);
    EXPECT_GT(w->balls()[0].z, 0.0) << name;
    w->runFor(0.2 * flight);
    const std::vector<Event> lands = eventsOf(*w, EventType::Land);
    ASSERT_FALSE(lands.empty()) << name;
    EXPECT_NEAR(lands[0].t, flight, 1e-12) << name;
    std::printf(
        "[ measured ] %s: 30 deg at 4 m/s: up at %.4f m/s, apex %.1f mm, %.3f m in the air\n", name,
        vz, 1e3 * vz * vz / (2.0 * p.gravity), vx * flight);
  }
}

TEST(Slate, ALevelStrokeAndAGentleElevatedOneStayOnTheCloth) {
  const PhysicsParams p = PhysicsParams::real();
  for (const double elevation_deg : {0.0, 5.0}) {
    Shot s = Shot::withSpeed(0.0, 2.0);
    s.elevation_rad = elevation_deg * kPi / 180.0;
    // 2 m/s at 5 deg comes back at 0.087 m/s: a 0.4 mm hop, under the least bounce.
    const Strike k = cueStrike(s, p.ball_mass, p);
    EXPECT_EQ(k.vz, 0.0) << elevation_deg;
  }
}

TEST(Slate, ATipUnderTheEquatorOfAJumpingStrokeIsAScoopAndAMiscue) {
  const PhysicsParams p = PhysicsParams::real();
  Shot s = Shot::withSpeed(0.0, 5.0);
  s.elevation_rad = 15.0 * kPi / 180.0;
  s.tip = {0.0, -0.45};  // cos 15 (-0.45) + sin 15 sqrt(1 - 0.45^2) < 0: below the equator
  EXPECT_TRUE(cueStrike(s, p.ball_mass, p).scoop);
  for (const char* name : kEngineNames) {
    const auto w = engineOf(name, p);
    w->addBall(BallState::at(0, {0.0, 0.0}));
    EXPECT_FALSE(w->strike(0, s)) << name;
    EXPECT_EQ(eventsOf(*w, EventType::Miscue).size(), 1u) << name;
  }
  s.tip = {0.0, 0.2};  // above: a jump
  EXPECT_FALSE(cueStrike(s, p.ball_mass, p).scoop);
  s.elevation_rad = 0.0;
  s.tip = {0.0, -0.45};  // a level draw is no scoop: the ball never leaves the cloth
  EXPECT_FALSE(cueStrike(s, p.ball_mass, p).scoop);
}

TEST(Slate, ASceneMayHoldABallInTheAirOverAnotherButNotInIt) {
  Scene scene;
  scene.balls = {BallState::at(0, {0.0, 0.0}), BallState::at(1, {0.001, 0.0})};
  scene.balls[1].z = 0.06;  // 60 mm up: clear of the ball beneath (two radii are 57 mm)
  EXPECT_FALSE(validateScene(scene).has_value()) << validateScene(scene).value_or("");
  scene.balls[1].z = 0.05;  // 50 mm: inside it
  ASSERT_TRUE(validateScene(scene).has_value());
  EXPECT_NE(validateScene(scene)->find("overlaps ball 0"), std::string::npos);
}

TEST(Slate, ThePapersClothsKeepEveryBallOnTheSlate) {
  for (const PhysicsParams& p : {PhysicsParams::paper()}) {
    Kinematics k;
    k.vz = 1.0;
    EXPECT_NE(beginArc(0.0, k, p).phase, Phase::Airborne);
    Shot s = Shot::withSpeed(0.0, 4.0);
    s.elevation_rad = 0.5;
    EXPECT_EQ(cueStrike(s, p.ball_mass, p).vz, 0.0);
  }
}

}  // namespace
}  // namespace nineball::physics
