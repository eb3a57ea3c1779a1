// A table may have any number of pockets, none included (carom): both engines run on four
// straight cushions, keep every ball on the cloth, and the pictures and checks accept it.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "nineball/engine.hpp"
#include "nineball/random.hpp"
#include "nineball/scenes.hpp"

namespace nineball {
namespace {

TableDef pocketless() {
  TableDef def;
  def.length = 2.84;
  def.width = 1.42;
  def.pockets = false;
  return def;
}

double energy(const std::vector<BallState>& balls, const PhysicsParams& p) {
  double e = 0.0;
  const double inertia = 0.4 * p.ball_mass * p.ball_radius * p.ball_radius;
  for (const BallState& b : balls) {
    e += 0.5 * p.ball_mass * dot(b.vel, b.vel) + 0.5 * inertia * dot(b.w, b.w);
  }
  return e;
}

TEST(PocketlessTable, IsFourStraightCushionsAndNoPockets) {
  const TableGeometry t = buildTable(pocketless(), 0.028575);
  EXPECT_TRUE(t.pockets.empty());
  ASSERT_EQ(t.cushion_loop.size(), 4u);
  EXPECT_EQ(cushionNoses(t).size(), 4u);
  EXPECT_EQ(clothOutline(t).size(), 8u);
  EXPECT_FALSE(checkTable(pocketless(), 0.028575));
  // Every corner is a place a ball can be frozen into, and no corner swallows it.
  const double r = 0.028575;
  EXPECT_TRUE(t.ballFits({1.42 - r, 0.71 - r}, r));
  EXPECT_FALSE(t.pocketAt({1.42 - r, 0.71 - r}));
}

TEST(PocketlessTable, BothEnginesKeepEveryBallOnTheClothAndPocketNone) {
  std::uint64_t rng = 5;
  for (const std::string& name : EngineKind::names()) {
    for (int shot = 0; shot < 8; ++shot) {
      StepParams step;
      step.engine = EngineKind::named(name);
      const PhysicsParams physics;
      auto engine = makeEngine(pocketless(), physics, step);
      const double r = physics.ball_radius;
      // Aimed into the corners too, where a pool table would have a pocket.
      engine->addBall(BallState::at(kCueBall, {-0.9, 0.2}));
      engine->addBall(BallState::at(1, {0.6, -0.1}));
      engine->addBall(BallState::at(2, {1.42 - r - 0.001, 0.71 - r - 0.001}));
      const double before = 0.5 * physics.ball_mass * 36.0;
      engine->strike(kCueBall, Shot::withSpeed(uniform(rng, -180.0, 180.0), 6.0));
      engine->runUntilRest();
      EXPECT_TRUE(engine->atRest()) << name;
      int cushions = 0;
      for (const Event& e : engine->events()) {
        EXPECT_NE(e.type, EventType::Pocket) << name << ", shot " << shot;
        if (e.type == EventType::Cushion) ++cushions;
      }
      EXPECT_GT(cushions, 0) << name << ", shot " << shot;
      for (const BallState& b : engine->balls()) {
        EXPECT_FALSE(b.pocket) << name;
        EXPECT_LE(std::abs(b.pos.x), 1.42 - r + 1e-6) << name << ", ball " << b.id;
        EXPECT_LE(std::abs(b.pos.y), 0.71 - r + 1e-6) << name << ", ball " << b.id;
      }
      EXPECT_LT(energy(engine->balls(), physics), before) << name;
    }
  }
}

}  // namespace
}  // namespace nineball
