// Snooker's opening position, spots by ball id and re-spotting (WPBSA 3.2, 3.7; the contract of
// issue 34), on the "snooker" table (3.569 x 1.778 m). The spots' distances themselves are
// tested with SnookerLayout (tests/physics/model/table_markings_test.cpp).
#include "games/snooker/snooker.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "games/snooker/respot.hpp"
#include "games/snooker/spots.hpp"
#include "nineball/games.hpp"
#include "nineball/table_markings.hpp"

namespace nineball {
namespace {

constexpr double kR = 0.02625;  // WPBSA section 1 rule 2: 52.5 mm
const TableDef kTable = TableDef::snooker();

TEST(SnookerTable, EachColourHasItsOwnSpotAndTheBlueTheCentre) {
  const SnookerLayout l = SnookerLayout::of(kTable);
  const std::pair<int, Vec2> spots[] = {{16, l.yellow}, {17, l.green}, {18, l.brown},
                                        {19, l.blue},   {20, l.pink},  {21, l.black}};
  for (const auto& [ball, spot] : spots) {
    EXPECT_EQ(snooker::colourSpot(kTable, ball).x, spot.x) << ball;
    EXPECT_EQ(snooker::colourSpot(kTable, ball).y, spot.y) << ball;
  }
  EXPECT_NEAR(snooker::colourSpot(kTable, 16).y, -0.292, 1e-12);  // yellow on the right
  EXPECT_NEAR(snooker::colourSpot(kTable, 21).x, 1.7845 - 0.324, 1e-12);
  const TableDef ten = TableDef::snookerTenFoot();
  EXPECT_NEAR(snooker::colourSpot(ten, 17).y, 0.292 * 10.0 / 12.0, 1e-12);
}

TEST(SnookerTable, TheCueBallInHandGoesInTheDItsLineAndArcIncluded) {
  const SnookerLayout l = SnookerLayout::of(kTable);
  const double xb = l.baulk_x;
  EXPECT_NEAR(xb, -1.7845 + 0.737, 1e-12);
  EXPECT_TRUE(inCueArea(CueArea::TheD, kTable, {xb, 0.292}));  // on the line and the arc
  EXPECT_TRUE(inCueArea(CueArea::TheD, kTable, {xb - 0.2, 0.0}));
  EXPECT_FALSE(inCueArea(CueArea::TheD, kTable, {xb + 0.01, 0.0}));  // the wrong side of the line
  EXPECT_FALSE(inCueArea(CueArea::TheD, kTable, {xb - 0.25, 0.2}));  // outside the semicircle
  EXPECT_EQ(cueAreaText(CueArea::TheD, kTable),
            "in the D (x <= -1.0475, within 0.2920 m of (-1.0475, 0))");
}

TEST(SnookerTable, TheRackPutsTheColoursOnTheirSpotsAndTheRedsBehindThePink) {
  const std::vector<BallState> balls = rackSnooker(kTable, kR, 1);
  ASSERT_EQ(balls.size(), 21u);
  const Vec2 pink = snooker::colourSpot(kTable, 20);
  double nearest_to_pink = 1.0;
  for (const BallState& b : balls) {
    if (b.id >= 16) {
      EXPECT_EQ(b.pos.x, snooker::colourSpot(kTable, b.id).x) << b.id;
      EXPECT_EQ(b.pos.y, snooker::colourSpot(kTable, b.id).y) << b.id;
      continue;
    }
    EXPECT_GT(b.pos.x, pink.x) << b.id;
    EXPECT_LT(b.pos.x, snooker::colourSpot(kTable, 21).x - 2.0 * kR) << b.id;
    nearest_to_pink = std::min(nearest_to_pink, length(b.pos - pink));
    for (const BallState& o : balls) {
      if (o.id != b.id) {
        EXPECT_GE(length(o.pos - b.pos), 2.0 * kR - 1e-12) << b.id << " " << o.id;
      }
    }
  }
  // The apex red as near the pink as it goes without touching (0.2 mm apart).
  EXPECT_GT(nearest_to_pink, 2.0 * kR);
  EXPECT_LT(nearest_to_pink, 2.0 * kR + 0.001);
}

TEST(SnookerRespot, OwnSpotWhenFree) {
  const TableGeometry t = buildTable(kTable, kR);
  const Vec2 p = snooker::respotPlace(19, t, kR, {BallState::at(1, {0.5, 0.3})});
  EXPECT_EQ(p.x, 0.0);
  EXPECT_EQ(p.y, 0.0);
}

TEST(SnookerRespot, TheHighestValueSpotFreeWhenItsOwnIsTaken) {
  const TableGeometry t = buildTable(kTable, kR);
  // A red on the black spot: the black goes to the pink's; with the pink there too, the blue's.
  std::vector<BallState> balls{BallState::at(1, snooker::colourSpot(kTable, 21))};
  Vec2 p = snooker::respotPlace(21, t, kR, balls);
  EXPECT_EQ(p.x, snooker::colourSpot(kTable, 20).x);
  balls.push_back(BallState::at(20, snooker::colourSpot(kTable, 20)));
  p = snooker::respotPlace(21, t, kR, balls);
  EXPECT_EQ(p.x, 0.0);
  EXPECT_EQ(p.y, 0.0);
}

std::vector<BallState> everySpotTaken() {
  std::vector<BallState> balls;
  for (int c = 16; c <= 21; ++c) {
    balls.push_back(BallState::at(c - 15, snooker::colourSpot(kTable, c)));
  }
  return balls;
}

TEST(SnookerRespot, NearItsSpotTowardsTheTopCushionWhenEverySpotIsTaken) {
  const TableGeometry t = buildTable(kTable, kR);
  const Vec2 blue = snooker::colourSpot(kTable, 19);
  const Vec2 p = snooker::respotPlace(19, t, kR, everySpotTaken());
  EXPECT_EQ(p.y, 0.0);
  EXPECT_GE(p.x, blue.x + 2.0 * kR);
  EXPECT_LT(p.x, blue.x + 2.0 * kR + 0.001);  // as near as the 0.5 mm search step allows
}

TEST(SnookerRespot, TowardsTheBottomCushionWhenTheWayUpIsFull) {
  const TableGeometry t = buildTable(kTable, kR);
  std::vector<BallState> balls = everySpotTaken();
  const Vec2 black = snooker::colourSpot(kTable, 21);
  for (int k = 1; k <= 5; ++k) balls.push_back(BallState::at(6 + k, {black.x + k * 2.0 * kR, 0.0}));
  const Vec2 p = snooker::respotPlace(21, t, kR, balls);
  EXPECT_EQ(p.y, 0.0);
  EXPECT_LE(p.x, black.x - 2.0 * kR);
  EXPECT_GT(p.x, black.x - 2.0 * kR - 0.001);
}

}  // namespace
}  // namespace nineball
