// The aim guide's geometry: ghost ball, directions after contact, cushions and pockets.
#include "play/aim_guide.hpp"

#include <gtest/gtest.h>

#include <cmath>

using nineball::AimGuide;
using nineball::AimTarget;
using nineball::BallState;
using nineball::buildTable;
using nineball::computeAimGuide;
using nineball::degToRad;
using nineball::PocketId;
using nineball::TableDef;
using nineball::TableGeometry;
using nineball::Vec2;

namespace {

constexpr double kR = 0.028575;
constexpr double kTol = 1e-9;

BallState ball(int id, Vec2 p) {
  BallState b;
  b.id = id;
  b.pos = p;
  return b;
}

class AimGuideTest : public ::testing::Test {
 protected:
  TableGeometry table = buildTable(TableDef{}, kR);

  AimGuide aim(const std::vector<BallState>& balls, Vec2 cue, double heading_deg) const {
    return computeAimGuide(table, kR, balls, cue, degToRad(heading_deg));
  }
};

}  // namespace

TEST_F(AimGuideTest, StraightShotStopsTheGhostBallTwoRadiiShort) {
  const AimGuide g = aim({ball(0, {-0.6, 0.0}), ball(1, {0.3, 0.0})}, {-0.6, 0.0}, 0.0);
  ASSERT_EQ(g.target, AimTarget::Ball);
  EXPECT_EQ(g.ball, 1);
  EXPECT_NEAR(g.end.x, 0.3 - 2.0 * kR, kTol);
  EXPECT_NEAR(g.end.y, 0.0, kTol);
  EXPECT_NEAR(g.object_dir.x, 1.0, kTol);
  EXPECT_NEAR(g.object_dir.y, 0.0, kTol);
  // A full hit: the stun cue ball stops, no tangent line.
  EXPECT_NEAR(length(g.cue_dir), 0.0, kTol);
  // The object ball runs on to the foot cushion.
  EXPECT_NEAR(g.object_end.x, table.def.length / 2.0 - kR, kTol);
  EXPECT_NEAR(g.object_end.y, 0.0, kTol);
}

TEST_F(AimGuideTest, TheObjectBallsPathStopsAtTheNextBall) {
  const AimGuide g = aim({ball(1, {0.0, 0.0}), ball(2, {0.4, 0.0})}, {-0.5, 0.0}, 0.0);
  ASSERT_EQ(g.ball, 1);
  EXPECT_NEAR(g.object_end.x, 0.4 - 2.0 * kR, kTol);
}

TEST_F(AimGuideTest, CutShotSendsTheBallsAlongTheLineOfCentresAndTheTangent) {
  // The object ball sits off the line by 2R sin(30 deg): a 30 degree cut.
  const double off = 2.0 * kR * std::sin(degToRad(30.0));
  const AimGuide g = aim({ball(3, {0.0, off})}, {-0.5, 0.0}, 0.0);
  ASSERT_EQ(g.target, AimTarget::Ball);
  EXPECT_EQ(g.ball, 3);
  EXPECT_NEAR(length(g.end - Vec2{0.0, off}), 2.0 * kR, kTol);
  EXPECT_NEAR(g.end.y, 0.0, kTol);
  // The object ball leaves 30 degrees off the aim line, from the ghost ball to its centre.
  EXPECT_NEAR(std::atan2(g.object_dir.y, g.object_dir.x), degToRad(30.0), 1e-9);
  // The cue ball goes off at 90 degrees to it, on the other side.
  EXPECT_NEAR(dot(g.cue_dir, g.object_dir), 0.0, kTol);
  EXPECT_NEAR(std::atan2(g.cue_dir.y, g.cue_dir.x), degToRad(-60.0), 1e-9);
}

TEST_F(AimGuideTest, TheNearestBallIsTheOneHit) {
  const AimGuide g =
      aim({ball(5, {0.4, 0.0}), ball(2, {0.1, 0.01}), ball(7, {0.7, 0.0})}, {-0.5, 0.0}, 0.0);
  ASSERT_EQ(g.target, AimTarget::Ball);
  EXPECT_EQ(g.ball, 2);
}

TEST_F(AimGuideTest, AGrazeHitsAndAHairWiderMisses) {
  const double reach = 2.0 * kR;
  EXPECT_EQ(aim({ball(4, {0.2, reach - 1e-7})}, {-0.5, 0.0}, 0.0).target, AimTarget::Ball);
  EXPECT_NE(aim({ball(4, {0.2, reach + 1e-7})}, {-0.5, 0.0}, 0.0).target, AimTarget::Ball);
}

TEST_F(AimGuideTest, PocketedBallsAndTheCueBallItselfAreNotInTheWay) {
  BallState gone = ball(6, {0.2, 0.0});
  gone.pocket = PocketId::TopSide;
  const AimGuide g = aim({ball(0, {-0.5, 0.0}), gone}, {-0.5, 0.0}, 0.0);
  EXPECT_NE(g.target, AimTarget::Ball);
}

TEST_F(AimGuideTest, AnEmptyPathEndsOnTheCushionOneRadiusOff) {
  // Along y = 0.2 to the foot cushion at x = length / 2.
  const AimGuide g = aim({}, {0.0, 0.2}, 0.0);
  ASSERT_EQ(g.target, AimTarget::Cushion);
  EXPECT_NEAR(g.end.x, table.def.length / 2.0 - kR, kTol);
  EXPECT_NEAR(g.end.y, 0.2, kTol);
  EXPECT_NEAR(g.cushion_normal.x, -1.0, kTol);
  EXPECT_NEAR(g.cushion_normal.y, 0.0, kTol);
  // Straight up to the long cushion at y = width / 2, well away from the side pocket.
  const AimGuide up = aim({}, {0.6, 0.0}, 90.0);
  ASSERT_EQ(up.target, AimTarget::Cushion);
  EXPECT_NEAR(up.end.y, table.def.width / 2.0 - kR, kTol);
  EXPECT_NEAR(up.cushion_normal.y, -1.0, kTol);
}

TEST_F(AimGuideTest, AShotIntoACornerDropsInThatPocket) {
  const Vec2 from{0.0, 0.0};
  const Vec2 corner = table.pockets[static_cast<int>(PocketId::TopRight)].drop_centre;
  const double heading = nineball::radToDeg(std::atan2(corner.y - from.y, corner.x - from.x));
  const AimGuide g = aim({}, from, heading);
  ASSERT_EQ(g.target, AimTarget::Pocket);
  EXPECT_EQ(g.pocket, PocketId::TopRight);
}

TEST_F(AimGuideTest, ABallFrozenToTheCushionIsStoppedAtOnce) {
  // The cue ball touches the foot cushion and is aimed into it.
  const Vec2 frozen{table.def.length / 2.0 - kR, 0.2};
  const AimGuide g = aim({}, frozen, 0.0);
  ASSERT_EQ(g.target, AimTarget::Cushion);
  EXPECT_NEAR(length(g.end - frozen), 0.0, 1e-6);
  // Aimed away from it, the path crosses the table.
  EXPECT_LT(aim({}, frozen, 180.0).end.x, 0.0);
}
