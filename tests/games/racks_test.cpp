// The eight-ball and ten-ball racks: on the table, no overlap, the standard constraints, for
// many seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "games/eight_ball/eight_ball.hpp"
#include "games/nine_ball/nine_ball.hpp"
#include "games/ten_ball/ten_ball.hpp"
#include "nineball/scenes.hpp"
#include "nineball/table.hpp"

namespace nineball {
namespace {

constexpr double kRadius = 0.028575;

const BallState& ball(const std::vector<BallState>& balls, int id) {
  return *std::find_if(balls.begin(), balls.end(), [id](const BallState& b) { return b.id == id; });
}

// Every ball fits the table, no two overlap, the ids are 1..n once each.
void expectSound(const std::vector<BallState>& balls, int n, const TableDef& def) {
  const TableGeometry table = buildTable(def, kRadius);
  std::set<int> ids;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    ids.insert(balls[i].id);
    EXPECT_TRUE(table.ballFits(balls[i].pos, kRadius)) << "ball " << balls[i].id;
    for (std::size_t j = i + 1; j < balls.size(); ++j) {
      EXPECT_GE(length(balls[i].pos - balls[j].pos), 2.0 * kRadius - 1e-12)
          << balls[i].id << " on " << balls[j].id;
    }
  }
  EXPECT_EQ(balls.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(ids.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(*ids.begin(), 1);
  EXPECT_EQ(*ids.rbegin(), n);
}

// The spot of the balls furthest from the head, at the ends of the back row.
std::vector<int> backCorners(const std::vector<BallState>& balls) {
  double back = -1e9;
  for (const BallState& b : balls) back = std::max(back, b.pos.x);
  std::vector<const BallState*> row;
  for (const BallState& b : balls) {
    if (b.pos.x > back - 1e-9) row.push_back(&b);
  }
  std::sort(row.begin(), row.end(), [](auto* l, auto* r) { return l->pos.y < r->pos.y; });
  return {row.front()->id, row.back()->id};
}

TEST(RackEightBall, FifteenBallsEightCentreSolidAndStripeInTheBackCorners) {
  std::set<std::vector<int>> layouts;
  for (const TableDef& def : {TableDef::nineFoot(), TableDef::sevenFoot()}) {
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
      const auto balls = rackEightBall(def, kRadius, seed);
      expectSound(balls, 15, def);
      const double row_step = 2.0 * kRadius * std::sqrt(3.0) / 2.0;
      const Vec2 centre{def.length / 4.0 + 2.0 * row_step, 0.0};
      EXPECT_LT(length(ball(balls, 8).pos - centre), 1e-12) << seed;
      const auto corners = backCorners(balls);
      const auto g0 = rules::groupOf(corners[0]);
      const auto g1 = rules::groupOf(corners[1]);
      ASSERT_TRUE(g0 && g1) << seed;
      EXPECT_NE(*g0, *g1) << seed;
      std::vector<int> order;
      for (const BallState& b : balls) order.push_back(b.id);
      layouts.insert(order);
    }
  }
  EXPECT_GT(layouts.size(), 250u);  // the seed places the balls
}

TEST(RackEightBall, AGapSpreadsTheRackWithoutOverlap) {
  const auto balls = rackEightBall(TableDef::nineFoot(), kRadius, 7, 0.001);
  expectSound(balls, 15, TableDef::nineFoot());
}

TEST(RackTenBall, TenBallsOneApexTenCentre) {
  std::set<std::vector<int>> layouts;
  for (const TableDef& def : {TableDef::nineFoot(), TableDef::sevenFoot()}) {
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
      const auto balls = rackTenBall(def, kRadius, seed);
      expectSound(balls, 10, def);
      const Vec2 foot{def.length / 4.0, 0.0};
      EXPECT_LT(length(ball(balls, 1).pos - foot), 1e-12) << seed;
      const double row_step = 2.0 * kRadius * std::sqrt(3.0) / 2.0;
      EXPECT_LT(length(ball(balls, 10).pos - Vec2{foot.x + 2.0 * row_step, 0.0}), 1e-12) << seed;
      for (const BallState& b : balls) EXPECT_GE(b.pos.x, foot.x - 1e-12);  // 1 in front
      std::vector<int> order;
      for (const BallState& b : balls) order.push_back(b.id);
      layouts.insert(order);
    }
  }
  EXPECT_GT(layouts.size(), 250u);
}

TEST(RackFor, PicksTheGamesRack) {
  const TableDef def;
  EXPECT_EQ(rackFor(rules::Game::NineBall, def, kRadius, 3).size(), 9u);
  EXPECT_EQ(rackFor(rules::Game::EightBall, def, kRadius, 3).size(), 15u);
  EXPECT_EQ(rackFor(rules::Game::TenBall, def, kRadius, 3).size(), 10u);
  const auto nine = rackFor(rules::Game::NineBall, def, kRadius, 3);
  const auto direct = rackNineBall(def, kRadius, 3);
  for (std::size_t i = 0; i < nine.size(); ++i) {
    EXPECT_EQ(nine[i].id, direct[i].id);
    EXPECT_EQ(nine[i].pos.x, direct[i].pos.x);
    EXPECT_EQ(nine[i].pos.y, direct[i].pos.y);
  }
}

}  // namespace
}  // namespace nineball
