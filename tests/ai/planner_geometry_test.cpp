// The geometry the planner reasons with before it simulates: which balls still have a way
// into a pocket.
#include "ai/planner_geometry.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "nineball/params.hpp"

namespace nineball::ai {
namespace {

const double kRadius = PhysicsParams{}.ball_radius;

BallState at(int id, Vec2 pos) {
  return BallState::at(id, pos);
}

TEST(PlannerGeometry, ABallInTheOpenHasAWayIntoAPocket) {
  const TableGeometry table = buildTable(TableDef{}, kRadius);
  const std::vector<BallState> balls = {at(0, {-0.5, 0.0}), at(3, {0.3, 0.1})};
  EXPECT_EQ(openShare(table, kRadius, balls, {3}), 1.0);
  EXPECT_EQ(openShare(table, kRadius, balls, {4, 5}), 1.0) << "none left: nothing to open";
}

TEST(PlannerGeometry, ABallInsideAClusterHasNone) {
  // The 3 ringed by six balls touching it: every straight path out meets one of them, while the
  // ring's own outer balls still see pockets.
  const TableGeometry table = buildTable(TableDef{}, kRadius);
  std::vector<BallState> balls = {at(0, {-0.8, 0.0}), at(3, {0.3, 0.1})};
  const double d = 2.0 * kRadius + 1e-4;
  for (int k = 0; k < 6; ++k) {
    const double a = k * kPi / 3.0;
    balls.push_back(at(9 + k, {0.3 + d * std::cos(a), 0.1 + d * std::sin(a)}));
  }
  EXPECT_EQ(openShare(table, kRadius, balls, {3}), 0.0);
  EXPECT_GT(openShare(table, kRadius, balls, {9, 10, 11, 12, 13, 14}), 0.5);
  // The cue ball is left out: it will have moved by the time the ball is played.
  const std::vector<BallState> behind_cue = {at(0, {0.3, 0.2}), at(3, {0.3, 0.1})};
  EXPECT_EQ(openShare(table, kRadius, behind_cue, {3}), 1.0);
}

}  // namespace
}  // namespace nineball::ai
