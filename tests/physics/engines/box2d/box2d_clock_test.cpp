// Box2D's step timers must not reach the real clock (a quarter of a break's time), and the
// rest of the process must still read the real time.
#include "physics/engines/box2d/box2d_clock.hpp"

#include <gtest/gtest.h>
#include <sys/time.h>

#include <chrono>
#include <cmath>

#include "nineball/scenes.hpp"
#include "nineball/sim.hpp"
#include "physics/engines/box2d/world.hpp"

namespace nineball::physics {
namespace {

TEST(MutedBox2DClock, ABreakReadsNoClockInsideBox2D) {
  const Scene scene = breakScene(1, 10.0);
  World world(scene.table, scene.physics, scene.step);
  for (const BallState& b : scene.balls) world.addBall(b);
  const long before = mutedClockReads();
  ASSERT_TRUE(world.strike(kCueBall, *scene.shot));
  world.runUntilRest();
  // Box2D 2.4.1 times each step, island and solver phase; the world steps it at the contacts
  // and sensors it resolves (a dozen a break). None would land here if the override were lost
  // and they went to the C library again.
  EXPECT_GT(mutedClockReads() - before, 0);
}

TEST(MutedBox2DClock, EveryoneElseReadsTheRealTime) {
  timeval tv{};
  ASSERT_EQ(gettimeofday(&tv, nullptr), 0);
  const double ours = static_cast<double>(tv.tv_sec) + 1e-6 * static_cast<double>(tv.tv_usec);
  const double now =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  EXPECT_LT(std::abs(ours - now), 1.0);
  {
    const MutedBox2DClock muted;
    const long before = mutedClockReads();
    ASSERT_EQ(gettimeofday(&tv, nullptr), 0);
    EXPECT_EQ(tv.tv_sec, 0);
    EXPECT_EQ(mutedClockReads(), before + 1);
  }
  ASSERT_EQ(gettimeofday(&tv, nullptr), 0);
  EXPECT_GT(tv.tv_sec, 1'600'000'000);  // after September 2020
}

}  // namespace
}  // namespace nineball::physics
