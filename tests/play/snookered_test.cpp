// "Snookered" as WPBSA section 2 defines it: a direct stroke in a straight line to every ball on
// is obstructed, wholly or in part, by a ball not on; a ball on hittable at both extreme edges
// means not snookered.
#include "play/snookered.hpp"

#include <gtest/gtest.h>

namespace nineball::play {
namespace {

constexpr double kR = 0.02625;  // a snooker ball (WPBSA: 52.5 mm across)

std::vector<BallState> balls(std::vector<std::pair<int, Vec2>> list) {
  std::vector<BallState> out{BallState::at(kCueBall, {0.0, 0.0})};
  for (const auto& [id, p] : list) out.push_back(BallState::at(id, p));
  return out;
}

TEST(Snookered, ABallNotOnStraightInFrontOfTheOnlyRedSnookers) {
  EXPECT_TRUE(snookered({0.0, 0.0}, {1}, balls({{1, {0.8, 0.0}}, {20, {0.3, 0.0}}}), kR));
}

TEST(Snookered, AClearPathToBothEdgesIsNotASnooker) {
  EXPECT_FALSE(snookered({0.0, 0.0}, {1}, balls({{1, {0.8, 0.0}}, {20, {0.3, 0.2}}}), kR));
}

TEST(Snookered, OneEdgeObstructedIsASnookerUnlessAnotherBallOnIsInFullView) {
  // The pink 45 mm off the line covers the red's upper edge only: that path passes 19 mm from
  // the pink's centre (inside 2R), the lower one 71 mm (clear).
  const auto partial = balls({{1, {0.8, 0.0}}, {20, {0.4, 0.045}}});
  EXPECT_TRUE(snookered({0.0, 0.0}, {1}, partial, kR));
  auto with_free_red = partial;
  with_free_red.push_back(BallState::at(2, {-0.5, 0.3}));
  EXPECT_FALSE(snookered({0.0, 0.0}, {1, 2}, with_free_red, kR));
}

TEST(Snookered, ABallOnNeverSnookersAnother) {
  EXPECT_FALSE(snookered({0.0, 0.0}, {1, 2}, balls({{1, {0.8, 0.0}}, {2, {0.3, 0.0}}}), kR));
}

TEST(Snookered, ACueBallTouchingABallOnIsNotSnookered) {
  const auto b = balls({{1, {2.0 * kR + 1e-6, 0.0}}, {20, {-0.2, 0.0}}});
  EXPECT_FALSE(snookered({0.0, 0.0}, {1}, b, kR));
  EXPECT_EQ(touchingBalls({0.0, 0.0}, b, kR), std::vector<int>{1});
}

TEST(Snookered, PocketedBallsNeitherObstructNorCount) {
  auto b = balls({{1, {0.8, 0.0}}, {20, {0.3, 0.0}}});
  b[2].pocket = PocketId::TopLeft;
  EXPECT_FALSE(snookered({0.0, 0.0}, {1}, b, kR));
  b[1].pocket = PocketId::TopLeft;
  EXPECT_FALSE(snookered({0.0, 0.0}, {1}, b, kR));  // no ball on at all: nothing to snooker
}

}  // namespace
}  // namespace nineball::play
