// The game environment's tables: what a step pays, its errors, the episode's end, and the same
// play on any number of threads.
#include "env/vec_tables.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace nineball::env {
namespace {

Action stroke(double heading_deg, double speed) {
  Action a;
  a.shot = Shot::withSpeed(heading_deg, speed);
  return a;
}

std::vector<Action> strokes(std::size_t n, int round) {
  std::vector<Action> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(stroke(37.0 * (i + 1) + 11.0 * round, 2.5));
  return out;
}

TEST(VecTables, EveryTablePlaysTheSameOnOneThreadAsOnTwo) {
  const EnvSpec spec = EnvSpec::named("pot", std::nullopt, "club");
  VecTables one(spec, 12, 7, 1);
  VecTables two(spec, 12, 7, 2);
  for (int round = 0; round < 3; ++round) {
    const auto a = one.step(strokes(12, round), true);
    const auto b = two.step(strokes(12, round), true);
    for (std::size_t i = 0; i < 12; ++i) {
      EXPECT_EQ(a[i].reward, b[i].reward);
      EXPECT_EQ(a[i].executed.shot.heading_rad, b[i].executed.shot.heading_rad);
      EXPECT_EQ(one.at(i).match().balls()[0].pos.x, two.at(i).match().balls()[0].pos.x);
    }
  }
}

TEST(VecTables, APotTaskStrokeEndsTheEpisodeAndIsPaidForThePotOnly) {
  TableEnv table(EnvSpec::named("pot", std::nullopt, "none"));
  int paid = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    table.reset(seed);
    const std::vector<BallState> balls = table.match().balls();
    const Vec2 to = balls[1].pos - balls[0].pos;
    const StepOutcome out = table.step(stroke(std::atan2(to.y, to.x) * 180.0 / M_PI, 3.0));
    EXPECT_TRUE(out.terminated);
    EXPECT_FALSE(out.truncated);
    const bool down = table.match().balls()[1].pocket.has_value();
    EXPECT_EQ(out.potted, down ? 1 : 0);
    EXPECT_EQ(out.reward, (down && out.legal ? 1.0 : 0.0) + (out.legal ? 0.0 : -1.0));
    paid += out.reward > 0.0 ? 1 : 0;
    EXPECT_THROW(table.step(stroke(0.0, 1.0)), IllegalAction);
  }
  EXPECT_GT(paid, 0) << "straight at the ball's centre from anywhere, some drop";
}

TEST(VecTables, WithoutNoiseTheStrokeIsPlayedAsAskedAndWithItItErrs) {
  TableEnv exact(EnvSpec::named("pot", std::nullopt, "none"));
  TableEnv noisy(EnvSpec::named("pot", std::nullopt, "olympiad"));
  const Action a = stroke(12.0, 2.0);
  EXPECT_EQ(exact.step(a).executed.shot.heading_rad, a.shot.heading_rad);
  EXPECT_NE(noisy.step(a).executed.shot.heading_rad, a.shot.heading_rad);
}

TEST(VecTables, AgainstTheComputerTheAgentIsAlwaysToShootOrTheRackIsOver) {
  VecTables tables(EnvSpec::named("nine-ball", std::string("beginner"), "none"), 2, 3, 2);
  for (int round = 0; round < 4; ++round) {
    std::vector<Action> actions;
    for (std::size_t i = 0; i < 2; ++i) actions.push_back(tables.at(i).completed(stroke(0.0, 6.0)));
    tables.step(actions, true);
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_EQ(tables.at(i).match().rack().shooter(), rules::Player::A);
    }
  }
}

TEST(VecTables, UnknownNamesAreRefusedByName) {
  EXPECT_THROW(EnvSpec::named("nine-pin", std::nullopt, "none"), std::invalid_argument);
  EXPECT_THROW(EnvSpec::named("pot", std::string("club"), "none"), std::invalid_argument);
  EXPECT_THROW(EnvSpec::named("pot", std::nullopt, "olympic"), std::invalid_argument);
  EXPECT_THROW(EnvSpec::named("pot", std::nullopt, "none", "bullet"), std::invalid_argument);
}

}  // namespace
}  // namespace nineball::env
