// The bank line: the aim guide's path mirrored off the first cushion and traced on.
#include "play/bank_guide.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "nineball/table.hpp"

namespace nineball {
namespace {

constexpr double kR = 0.028575;

TEST(BankGuide, MirrorsThePathInTheCushionAndTracesItOn) {
  const TableGeometry table = buildTable(TableDef{}, kR);
  const std::vector<BallState> balls = {BallState::at(kCueBall, {-0.3, 0.0})};
  // Up and to the right, to the top rail, then down and to the right.
  const double heading = std::atan2(1.0, 1.0);
  const AimGuide guide = computeAimGuide(table, kR, balls, {-0.3, 0.0}, heading);
  ASSERT_EQ(guide.target, AimTarget::Cushion);
  const auto bank = bankGuide(table, kR, balls, guide);
  ASSERT_TRUE(bank);
  EXPECT_EQ(bank->start, guide.end);
  const Vec2 d = normalized(bank->end - bank->start);
  EXPECT_NEAR(d.x, std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(d.y, -std::sqrt(0.5), 1e-9);
  EXPECT_LT(bank->end.y, guide.end.y);
  EXPECT_GT(length(bank->end - bank->start), 0.1);
}

TEST(BankGuide, NothingWhenTheGuideMeetsABallFirst) {
  const TableGeometry table = buildTable(TableDef{}, kR);
  const std::vector<BallState> balls = {BallState::at(kCueBall, {-0.3, 0.0}),
                                        BallState::at(1, {0.3, 0.0})};
  const AimGuide guide = computeAimGuide(table, kR, balls, {-0.3, 0.0}, 0.0);
  ASSERT_EQ(guide.target, AimTarget::Ball);
  EXPECT_FALSE(bankGuide(table, kR, balls, guide));
}

}  // namespace
}  // namespace nineball
