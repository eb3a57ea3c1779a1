#include "nineball/table_markings.hpp"

#include <gtest/gtest.h>

namespace nineball {
namespace {

// WPBSA Official Rules, section 1: distances on a full-size table (3569 mm between the
// cushion faces), to the millimetre the rules give them in.
constexpr double kMm = 1e-3;

TableDef fullSizeSnooker() {
  TableDef t{3.569, 1.778};
  t.marks = TableMarks::Snooker;
  return t;
}

TEST(TableMarkings, SnookerSpotsWhereTheRulesPutThem) {
  const TableDef t = fullSizeSnooker();
  const SnookerLayout l = SnookerLayout::of(t);
  const double bottom = -t.length / 2.0, top = t.length / 2.0;
  EXPECT_NEAR(l.baulk_x - bottom, 0.737, kMm);
  EXPECT_NEAR(l.d_radius, 0.292, kMm);
  EXPECT_NEAR(top - l.black.x, 0.324, kMm);
  EXPECT_NEAR(l.pink.x, top / 2.0, kMm);  // midway between the centre spot and the top cushion
  EXPECT_NEAR(length(l.blue), 0.0, kMm);
  EXPECT_NEAR(l.brown.x, l.baulk_x, kMm);
  // Yellow on the right of the D seen from the baulk end (looking along +x, right is -y).
  EXPECT_LT(l.yellow.y, 0.0);
  EXPECT_GT(l.green.y, 0.0);
  EXPECT_NEAR(length(l.yellow - l.brown), 0.292, kMm);
  EXPECT_NEAR(length(l.green - l.brown), 0.292, kMm);
}

TEST(TableMarkings, SmallerSnookerTableKeepsTheProportions) {
  TableDef t = fullSizeSnooker();
  t.length *= 10.0 / 12.0;
  t.width *= 10.0 / 12.0;
  const SnookerLayout l = SnookerLayout::of(t);
  EXPECT_NEAR(l.d_radius, 0.292 * 10.0 / 12.0, kMm);
  EXPECT_NEAR(t.length / 2.0 - l.black.x, 0.324 * 10.0 / 12.0, kMm);
}

TEST(TableMarkings, TheDHoldsItsInsideOnly) {
  const SnookerLayout l = SnookerLayout::of(fullSizeSnooker());
  EXPECT_TRUE(l.inD(l.brown));
  EXPECT_TRUE(l.inD(l.brown + Vec2{-0.2, 0.1}));
  EXPECT_TRUE(l.inD(l.yellow));
  EXPECT_FALSE(l.inD(l.brown + Vec2{0.01, 0.0}));   // in front of the baulk line
  EXPECT_FALSE(l.inD(l.brown + Vec2{-0.25, 0.2}));  // behind the line, outside the half circle
}

TEST(TableMarkings, SnookerDrawsBaulkLineDAndSixSpotsPoolItsHeadStringAndFootSpot) {
  const TableMarkings snooker = markingsOf(fullSizeSnooker());
  EXPECT_EQ(snooker.lines.size(), 1u);
  EXPECT_EQ(snooker.arcs.size(), 1u);
  EXPECT_EQ(snooker.spots.size(), 6u);
  const TableMarkings pool = markingsOf(TableDef::nineFoot());
  ASSERT_EQ(pool.lines.size(), 1u);
  EXPECT_NEAR(pool.lines[0].a.x, -2.54 / 4.0, 1e-12);
  ASSERT_EQ(pool.spots.size(), 1u);
  EXPECT_NEAR(pool.spots[0].x, 2.54 / 4.0, 1e-12);
  EXPECT_TRUE(pool.arcs.empty());
}

}  // namespace
}  // namespace nineball
