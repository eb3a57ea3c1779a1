#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "nineball/scenes.hpp"
#include "physics/physics_fixtures.hpp"

namespace nineball::physics_test {
namespace {

// Velocities live in Box2D as floats: kinetic energy may wobble by their rounding, never more.
constexpr double kEnergyRounding = 1e-6;
// Positions live in Box2D as floats (metres x 100): a micrometre is above their rounding.
constexpr double kOverlapRounding = 1e-6;

double kineticEnergy(const World& w) {
  double ke = 0.0;
  // Translation and rotation (I = 2/5 m R^2): spin turns into speed and back, the sum only
  // falls.
  const double r = w.physics().ball_radius;
  for (const BallState& b : w.balls()) {
    const double m = b.mass.value_or(0.0);
    const double spin2 = b.w.x * b.w.x + b.w.y * b.w.y + b.w.z * b.w.z;
    ke += 0.5 * m * dot(b.vel, b.vel) + 0.5 * 0.4 * m * r * r * spin2;
  }
  return ke;
}

// Over a whole break, step by step: with e <= 1 everywhere and a cloth that only slows, the
// kinetic energy never grows; balls never sink into one another (the pairwise model resolves
// every contact where it happens); no ball leaves the cushion loop except into a pocket; the
// events come in time order and the run ends at rest.
TEST(Invariants, BreakKeepsThePhysicalInvariants) {
  WorstError gain("break: largest kinetic-energy gain in one step / initial KE", kEnergyRounding);
  WorstError overlap("break: deepest overlap of two balls, m", kOverlapRounding, "m");
  for (double speed : {3.0, 13.0}) {
    for (double hz : {120.0, 500.0}) {
      Scene scene = breakScene(1, speed);
      scene.step.hz = hz;
      World world(scene.table, scene.physics, scene.step);
      for (const BallState& b : scene.balls) world.addBall(b);
      world.strike(kCueBall, *scene.shot);
      const std::string where = "speed " + std::to_string(speed) + " hz " + std::to_string(hz);
      const double ke0 = kineticEnergy(world);
      double previous = ke0, worst_gain = 0.0, worst_overlap = 0.0;
      bool inside = true;
      const double limit = 60.0 * hz;
      while (!world.atRest() && world.steps() < limit) {
        world.step();
        const double ke = kineticEnergy(world);
        worst_gain = std::max(worst_gain, (ke - previous) / ke0);
        previous = ke;
        const auto balls = world.balls();
        for (std::size_t i = 0; i < balls.size(); ++i) {
          if (balls[i].pocket) continue;
          inside = inside && world.table().insideLoop(balls[i].pos);
          for (std::size_t j = i + 1; j < balls.size(); ++j) {
            if (balls[j].pocket) continue;
            const double d = length(balls[i].pos - balls[j].pos);
            worst_overlap = std::max(worst_overlap, 2.0 * scene.physics.ball_radius - d);
          }
        }
      }
      gain.check(worst_gain, where);
      overlap.check(worst_overlap, where);
      EXPECT_TRUE(inside) << where;
      EXPECT_TRUE(world.atRest()) << where;
      const auto& events = world.events();
      ASSERT_FALSE(events.empty()) << where;
      EXPECT_EQ(events.back().type, EventType::AllAtRest) << where;
      EXPECT_TRUE(std::is_sorted(events.begin(), events.end(), [](const Event& a, const Event& b) {
        return a.t < b.t;
      })) << where;
    }
  }
}

}  // namespace
}  // namespace nineball::physics_test
