// Balls meeting in space: a jump clears a blocking ball and pockets the ball behind it; a flight
// too low meets the blocker where their centres are two radii apart in space, and drives it
// into the slate; no contact in the air gives energy back. In both engines.
#include "physics/resolve/ball_ball/collide_in_air.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include "nineball/engine.hpp"
#include "physics/model/slate.hpp"

namespace nineball::physics {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// The cue ball, a blocker `blocker` m along the line to the top right corner pocket, and an
// object ball `object` m along it; the cue ball struck along the line.
struct JumpTable {
  JumpTable(const char* engine, double blocker, double object, double speed, double elevation_deg) {
    StepParams step;
    step.engine = EngineKind::named(engine);
    w = makeEngine(TableDef{}, PhysicsParams::real(), step);
    const Vec2 from{-0.6, -0.3};
    const Vec2 d = normalized(Vec2{1.27, 0.635} - from);
    w->addBall(BallState::at(0, from));
    w->addBall(BallState::at(1, from + d * blocker));
    w->addBall(BallState::at(2, from + d * object));
    shot = Shot::withSpeed(std::atan2(d.y, d.x) / kDegree, speed);
    shot.elevation_rad = elevation_deg * kDegree;
  }
  std::vector<Event> contacts(int ball) const {
    std::vector<Event> out;
    for (const Event& e : w->events()) {
      if (e.type == EventType::BallBall && (e.a == ball || e.b == ball)) out.push_back(e);
    }
    return out;
  }
  std::unique_ptr<Engine> w;
  Shot shot;
};

TEST(CollideInAir, AJumpClearsTheBlockerAndPocketsTheBallBehindIt) {
  for (const char* engine : {"reference", "box2d"}) {
    JumpTable t(engine, 0.35, 1.85, 4.5, 35.0);
    ASSERT_TRUE(t.w->strike(0, t.shot));
    t.w->runUntilRest();
    EXPECT_TRUE(t.contacts(1).empty()) << engine << ": the blocker was touched";
    EXPECT_EQ(length(t.w->balls()[1].vel), 0.0) << engine;
    EXPECT_TRUE(t.w->balls()[2].pocket.has_value()) << engine << ": the ball behind stayed up";
    ASSERT_FALSE(t.contacts(2).empty()) << engine;
  }
  // Level, the same stroke meets the blocker first.
  JumpTable level("reference", 0.35, 1.85, 4.5, 0.0);
  ASSERT_TRUE(level.w->strike(0, level.shot));
  level.w->runUntilRest();
  ASSERT_FALSE(level.contacts(1).empty());
  EXPECT_EQ(level.contacts(1).front().b, 1);
}

TEST(CollideInAir, AFlightTooLowMeetsTheBlockerTwoRadiiAwayInSpaceAndDrivesItDown) {
  // 4 m/s at 30 deg peaks at 51 mm, under the 57 mm a ball must clear.
  const double r = PhysicsParams::real().ball_radius;
  for (const char* engine : {"reference", "box2d"}) {
    JumpTable t(engine, 0.35, 1.85, 4.0, 30.0);
    ASSERT_TRUE(t.w->strike(0, t.shot));
    t.w->runUntilRest();
    const std::vector<Event> hits = t.contacts(1);
    ASSERT_FALSE(hits.empty()) << engine;
    const double at = hits.front().t;
    // Struck from 50 mm up, the blocker is driven into the slate, which throws it up: a hop.
    bool hopped = false;
    for (const Event& e : t.w->events()) hopped |= e.type == EventType::Airborne && e.a == 1;
    EXPECT_TRUE(hopped) << engine;
    JumpTable again(engine, 0.35, 1.85, 4.0, 30.0);
    ASSERT_TRUE(again.w->strike(0, again.shot));
    again.w->runFor(at * (1.0 - 1e-12));
    const std::vector<BallState> b = again.w->balls();
    ASSERT_GT(b[0].z, 0.0) << engine << ": met in the air";
    const Vec2 d = b[1].pos - b[0].pos;
    const double apart = std::sqrt(dot(d, d) + (b[1].z - b[0].z) * (b[1].z - b[0].z));
    // Box2D holds positions in floats (metres x 50): 1e-6 m; the reference engine to rounding.
    EXPECT_NEAR(apart, 2.0 * r, 1e-6) << engine;
    std::printf("[ measured ] %s: met at %.4f s, the cue ball %.1f mm up, %.9f m apart (2R %.9f)\n",
                engine, at, 1e3 * b[0].z, apart, 2.0 * r);
  }
}

TEST(CollideInAir, ABallDroppedOntoAnotherBouncesOffAndNeverSinksIntoIt) {
  const double r = PhysicsParams::real().ball_radius;
  for (const char* engine : {"reference", "box2d"}) {
    StepParams step;
    step.engine = EngineKind::named(engine);
    const auto w = makeEngine(TableDef{}, PhysicsParams::real(), step);
    BallState top = BallState::at(0, {0.005, 0.0});
    top.z = 0.1;  // dropped from 10 cm above the ball beneath, 5 mm off its centre
    w->addBall(top);
    w->addBall(BallState::at(1, {0.0, 0.0}));
    double closest = 1.0;
    for (int n = 0; n < 3000 && !w->atRest(); ++n) {
      w->runFor(0.001);
      const std::vector<BallState> b = w->balls();
      const Vec2 d = b[1].pos - b[0].pos;
      closest = std::min(closest, std::sqrt(dot(d, d) + (b[1].z - b[0].z) * (b[1].z - b[0].z)));
    }
    EXPECT_TRUE(w->atRest()) << engine;
    EXPECT_FALSE(w->exhausted()) << engine;
    EXPECT_GE(closest, 2.0 * r - 1e-6) << engine;
    EXPECT_EQ(w->balls()[0].z, 0.0) << engine;
  }
}

TEST(CollideInAir, NoContactInTheAirGivesEnergyBack) {
  PhysicsParams p = PhysicsParams::real();
  const double m = p.ball_mass, r = p.ball_radius, g = p.gravity;
  std::mt19937_64 rng(4949);
  std::uniform_real_distribution<double> speed(-5.0, 5.0), spin(-200.0, 200.0), unit(-1.0, 1.0);
  std::uniform_real_distribution<double> height(0.0, 0.06);
  int hops = 0;
  for (int n = 0; n < 100000; ++n) {
    Kinematics a, b;
    a.z = height(rng);
    a.v = {speed(rng), speed(rng)};
    a.vz = speed(rng);
    a.w = {spin(rng), spin(rng), spin(rng)};
    b.v = {speed(rng) * 0.2, speed(rng) * 0.2};
    b.w = {spin(rng), spin(rng), spin(rng)};
    // b on the cloth, two radii from a in a random direction below a's height.
    Vec3 n3{unit(rng), unit(rng), -std::abs(unit(rng))};
    const double len = std::sqrt(n3.x * n3.x + n3.y * n3.y + n3.z * n3.z);
    if (len < 1e-3) continue;
    b.p = a.p + Vec2{n3.x, n3.y} * (2.0 * r / len);
    b.z = a.z + n3.z * 2.0 * r / len;
    if (b.z < 0.0) continue;  // it would be in the slate
    b.z = 0.0;
    const double before = mechanicalEnergy(a, m, r, g) + mechanicalEnergy(b, m, r, g);
    collideInAir(a, b, m, m, p);
    const double after = mechanicalEnergy(a, m, r, g) + mechanicalEnergy(b, m, r, g);
    ASSERT_LE(after, before * (1.0 + 1e-12)) << n;
    if (b.vz > 0.0) ++hops;
  }
  std::printf("[ measured ] balls on the cloth struck from above that hop: %d\n", hops);
}

}  // namespace
}  // namespace nineball::physics

namespace nineball::physics {
namespace {

TEST(OffTable, AHardJumpAtARailFliesOverItAndOffTheTable) {
  const PhysicsParams p = PhysicsParams::real();
  for (const char* engine : {"reference", "box2d"}) {
    StepParams step;
    step.engine = EngineKind::named(engine);
    const auto w = makeEngine(TableDef{}, p, step);
    w->addBall(BallState::at(0, {0.3, 0.3}));
    Shot s = Shot::withSpeed(90.0, 8.0);  // at the top rail, 0.3 m away
    s.elevation_rad = 45.0 * kDegree;
    ASSERT_TRUE(w->strike(0, s));
    w->runUntilRest();
    bool left = false;
    for (const Event& e : w->events()) left |= e.type == EventType::OffTable && e.a == 0;
    EXPECT_TRUE(left) << engine;
    const BallState b = w->balls()[0];
    EXPECT_TRUE(b.off_table) << engine;
    EXPECT_TRUE(b.pocket.has_value()) << engine << ": off the table, as every ball not on it";
    // Where it crossed the cushion: a radius inside the cushion line (the nose it cleared).
    EXPECT_NEAR(b.pos.y, TableDef{}.width / 2.0 - p.ball_radius, 1e-6) << engine;
    EXPECT_NEAR(b.pos.x, 0.3, 1e-9) << engine;
  }
}

TEST(OffTable, AJumpUnderTheNoseMeetsTheCushion) {
  const PhysicsParams p = PhysicsParams::real();
  for (const char* engine : {"reference", "box2d"}) {
    StepParams step;
    step.engine = EngineKind::named(engine);
    const auto w = makeEngine(TableDef{}, p, step);
    // 2 cm from the cushion, rising at 0.6 m/s: 2.5 mm up when it meets it, under the 36 mm nose.
    BallState b =
        BallState::at(0, {0.3, TableDef{}.width / 2.0 - p.ball_radius - 0.02}, {0.0, 2.0});
    b.vz = 0.6;
    w->addBall(b);
    w->runUntilRest();
    int cushions = 0;
    for (const Event& e : w->events()) {
      EXPECT_NE(e.type, EventType::OffTable) << engine;
      cushions += e.type == EventType::Cushion;
    }
    EXPECT_GE(cushions, 1) << engine;
    EXPECT_FALSE(w->balls()[0].off_table) << engine;
  }
}

}  // namespace
}  // namespace nineball::physics
