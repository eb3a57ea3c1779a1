#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "physics/physics_fixtures.hpp"

namespace nineball::physics_test {
namespace {

// How far outside (or inside) the drop circle a ball is made to stop in the lip tests: far
// more than the stopping-distance error (0.5 % of 0.3 m would be 1.5 mm; measured far less).
constexpr double kLipMargin = 0.002;
// Box2D keeps positions as floats (in units of metres x k): a micrometre is far above
// their rounding and far below any real drift.
constexpr double kSinglePrecision = 1e-6;

double stoppingDistance(const PhysicsParams& p, double v0) {
  return v0 * v0 / (2.0 * p.rolling_friction * p.gravity);
}
double speedToStopIn(const PhysicsParams& p, double distance) {
  return std::sqrt(2.0 * p.rolling_friction * p.gravity * distance);
}

TEST(Pocket, EachPocketTakesABallSentIntoIt) {
  const PhysicsParams p = constantDeceleration();
  const TableGeometry table = buildTable(TableDef{}, p.ball_radius);
  for (const Pocket& pocket : table.pockets) {
    const std::string name = pocketName(pocket.id);
    const Vec2 start = pocket.drop_centre - pocket.outward * 0.5;
    auto world =
        makeWorld(TableDef{}, p, StepParams{}, {makeBall(kCueBall, start, pocket.outward * 2.0)});
    world->runUntilRest();
    const auto drop = firstEvent(world->events(), EventType::Pocket);
    ASSERT_TRUE(drop.has_value()) << name;
    EXPECT_EQ(drop->a, kCueBall);
    EXPECT_STREQ(pocketName(drop->pocket), name.c_str());
    EXPECT_EQ(countEvents(world->events(), EventType::Pocket), 1) << name;
    EXPECT_EQ(countEvents(world->events(), EventType::Cushion), 0) << name << ": touched a jaw";
    const BallState dropped = stateOf(*world, kCueBall);
    ASSERT_TRUE(dropped.pocket.has_value()) << name;
    EXPECT_EQ(*dropped.pocket, pocket.id);
    // Dropped the instant its centre entered the drop circle, and it stays there.
    EXPECT_NEAR(length(dropped.pos - pocket.drop_centre), pocket.drop_radius, kSinglePrecision)
        << name;
    EXPECT_EQ(dropped.vel, Vec2{});
    for (int i = 0; i < 10; ++i) world->step();
    const BallState later = stateOf(*world, kCueBall);
    EXPECT_EQ(later.pos, dropped.pos) << name;
    EXPECT_EQ(later.vel, Vec2{}) << name;
    EXPECT_EQ(countEvents(world->events(), EventType::Pocket), 1) << name;
  }
}

// Inward normal of the loop segment a -> b (the loop is clockwise: the table is on its right).
Vec2 inwardNormal(Vec2 a, Vec2 b) {
  const Vec2 d = normalized(b - a);
  return {d.y, -d.x};
}

TEST(Pocket, JawPointSendsTheBallStraightBack) {
  // A ball driven at a jaw point along the bisector of the rail's and the jaw face's normals
  // meets the point itself head on: it must come straight back at e_c times its speed and
  // stay on the table. (A ball cannot reach a jaw face square on: the corner faces run almost
  // along the pocket's axis and the side faces lie inside the drop circle; balls that glance
  // off a face go down, as they do on a real table.)
  WorstError rebound("pocket jaw point: velocity after", kCushionTolerance);
  PhysicsParams p = constantDeceleration();
  const double approach = 0.1, v0 = 0.5;
  const TableGeometry table = buildTable(TableDef{}, p.ball_radius);
  const auto& loop = table.cushion_loop;
  for (const Pocket& pocket : table.pockets) {
    for (const Vec2 jaw : {pocket.jaw_a, pocket.jaw_b}) {
      std::size_t i = 0;
      while (i < loop.size() && loop[i] != jaw) ++i;
      ASSERT_LT(i, loop.size());
      const Vec2 before = loop[(i + loop.size() - 1) % loop.size()];
      const Vec2 after = loop[(i + 1) % loop.size()];
      const Vec2 n = normalized(inwardNormal(before, jaw) + inwardNormal(jaw, after));
      const Vec2 start = jaw + n * (p.ball_radius + approach);
      const std::string where = std::string(pocketName(pocket.id)) + " jaw (" +
                                std::to_string(jaw.x) + ", " + std::to_string(jaw.y) + ")";
      auto world = makeWorld(TableDef{}, p, StepParams{}, {makeBall(kCueBall, start, -n * v0)});
      const auto hit = runUntilEvent(*world, EventType::Cushion, 2.0);
      ASSERT_TRUE(hit.has_value()) << where;
      const double u = std::sqrt(v0 * v0 - 2.0 * p.rolling_friction * p.gravity * approach);
      rebound.check(vectorError(hit->va, n * (p.cushion_restitution * u), v0), where);
      world->runUntilRest();
      EXPECT_EQ(countEvents(world->events(), EventType::Pocket), 0) << where;
      EXPECT_FALSE(stateOf(*world, kCueBall).pocket.has_value()) << where;
    }
  }
}

TEST(Pocket, BallRollingAlongTheRailPassesTheSidePocket) {
  // Parallel to the long rail, its edge 5 mm (then 1 mm) off the cushion nose, past the
  // side pocket's mouth: it must neither drop nor touch a jaw, and stop where the cloth
  // says, beyond the mouth.
  WorstError distance("pocket: rail-side roll past the side pocket, stopping distance",
                      kStoppingTolerance);
  const PhysicsParams p = constantDeceleration();
  const TableDef t;
  const double v0 = 0.4;
  for (double gap : {0.005, 0.001}) {
    for (double side : {1.0, -1.0}) {
      const Vec2 start{-0.4 * side, side * (t.width / 2.0 - p.ball_radius - gap)};
      auto world = makeWorld(t, p, StepParams{}, {makeBall(kCueBall, start, {side * v0, 0.0})});
      world->runUntilRest();
      const std::string where = "gap " + std::to_string(gap) + " side " + std::to_string(side);
      EXPECT_EQ(countEvents(world->events(), EventType::Pocket), 0) << where;
      EXPECT_EQ(countEvents(world->events(), EventType::Cushion), 0) << where;
      const BallState b = stateOf(*world, kCueBall);
      EXPECT_FALSE(b.pocket.has_value()) << where;
      EXPECT_NEAR(b.pos.y, start.y, kSinglePrecision) << where;
      EXPECT_GT(side * b.pos.x, t.side_pocket / 2.0 + p.ball_radius) << where;
      distance.check(relativeError(side * (b.pos.x - start.x), stoppingDistance(p, v0), 1.0),
                     where);
    }
  }
}

TEST(Pocket, BallHangingOnTheLipStaysUp) {
  // A ball rolled straight into each pocket so that it stops with its centre 2 mm short of
  // the drop circle stays on the table; 2 mm past, it drops. The drop circle is the rule.
  const PhysicsParams p = constantDeceleration();
  const TableGeometry table = buildTable(TableDef{}, p.ball_radius);
  const double run = 0.3;
  for (const Pocket& pocket : table.pockets) {
    const Vec2 edge = pocket.drop_centre - pocket.outward * pocket.drop_radius;
    const Vec2 start = edge - pocket.outward * run;
    for (double past : {-kLipMargin, kLipMargin}) {
      const std::string where =
          std::string(pocketName(pocket.id)) + " stop " + std::to_string(past) + " m past";
      const double v0 = speedToStopIn(p, run + past);
      auto world =
          makeWorld(TableDef{}, p, StepParams{}, {makeBall(kCueBall, start, pocket.outward * v0)});
      world->runUntilRest();
      EXPECT_EQ(countEvents(world->events(), EventType::Cushion), 0) << where;
      const BallState b = stateOf(*world, kCueBall);
      if (past < 0.0) {
        EXPECT_FALSE(b.pocket.has_value()) << where;
        EXPECT_EQ(countEvents(world->events(), EventType::Pocket), 0) << where;
        EXPECT_NEAR(length(b.pos - pocket.drop_centre), pocket.drop_radius - past, kLipMargin / 2.0)
            << where;
      } else {
        ASSERT_TRUE(b.pocket.has_value()) << where;
        EXPECT_EQ(*b.pocket, pocket.id) << where;
      }
    }
  }
}

}  // namespace
}  // namespace nineball::physics_test
