// A jam: contacts met again and again at one instant (see JamCounter), settled as one.
#include "physics/resolve/jam/jam.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "nineball/params.hpp"
#include "nineball/table.hpp"
#include "physics/resolve/ball_ball/ball_contact.hpp"
#include "physics/resolve/ball_ball/collide.hpp"
#include "physics/resolve/cushion/contact.hpp"
#include "physics/resolve/jam/jam_counter.hpp"

namespace nineball::physics {
namespace {

TEST(Jam, CountsContactsAtOneInstantOnly) {
  JamCounter jams;
  for (int n = 0; n < JamCounter::kJamContacts; ++n) EXPECT_FALSE(jams.jammed(1.0, 0, 1));
  EXPECT_TRUE(jams.jammed(1.0, 1, 2));  // ball 1's contact number kJamContacts + 1
  EXPECT_FALSE(jams.jammed(1.0, 2, JamCounter::kCushion));
  EXPECT_FALSE(jams.jammed(1.5, 0, 1));  // a new instant starts the count again
}

double energy(const Jam& jam) {
  double e = 0.0;
  for (const JamBall& b : jam.balls) e += 0.5 * b.mass * dot(b.k.v, b.k.v);
  return e;
}

TEST(Jam, APinnedLightBallStopsAHeavyOneInOneContact) {
  // A 10 g ball in a 90-degree wedge (faces x = 0 and y = 0), a 1 kg ball driving it in along
  // the diagonal. Pair by pair the heavy ball would lose 1 % of its approach per exchange;
  // settled together it stops along the line of centres at once.
  const double r = 0.028575;
  Jam jam;
  jam.balls.push_back({0, Kinematics{{r, r}, {0.0, 0.0}, {}}, 0.01, {{1.0, 0.0}, {0.0, 1.0}}});
  const Vec2 n = normalized(Vec2{1.0, 1.0});
  jam.balls.push_back({1, Kinematics{Vec2{r, r} + n * (2.0 * r), n * -1.0, {}}, 1.0, {}});
  jam.pairs = {{0, 1}};
  const double before = energy(jam);
  settleJam(jam, PhysicsParams::paper());
  EXPECT_LE(dot(jam.balls[0].k.v - jam.balls[1].k.v, n), kMinClosingSpeed);
  EXPECT_NEAR(length(jam.balls[0].k.v), 0.0, 1e-9);
  EXPECT_LE(energy(jam), before);
}

TEST(Jam, AStopAgainstTwoFacesLeavesNothingThatEntersEither) {
  // Into a wedge, along its bisector: nothing is left; along one face: that part stays.
  double impulse = 0.0;
  const std::vector<Vec2> faces{normalized(Vec2{1.0, 0.2}), normalized(Vec2{-1.0, 0.2})};
  Kinematics k{{0.0, 0.0}, {0.0, -2.0}, {}};
  EXPECT_NEAR(length(stopAgainst(k, faces, 0.17, impulse).v), 0.0, 1e-12);
  EXPECT_NEAR(impulse, 0.17 * 2.0, 1e-12);
  k.v = {1.0, 0.0};
  const Vec2 v = stopAgainst(k, faces, 0.17, impulse).v;
  for (Vec2 f : faces) EXPECT_GE(dot(v, f), -1e-12);
  EXPECT_LE(length(v), 1.0);
}

TEST(Jam, TwoBallsAcrossANarrowTableAreSetApartAlongTheirRails) {
  // One on each long rail of a table 3.5 R wide, pressed 5 um together: the line of centres
  // would push each into its rail, so they are set apart by sliding along them.
  const PhysicsParams p = PhysicsParams::paper();
  const double r = p.ball_radius;
  TableDef def;
  def.length = 1.0;
  def.width = 3.5 * r;
  def.corner_pocket = 0.02;
  def.side_pocket = 0.02;
  const TableGeometry t = buildTable(def, r);
  const double y = def.width / 2.0 - r;
  const double dx = std::sqrt(std::pow(2.0 * r - 5e-6, 2) - 4.0 * y * y);
  Kinematics a{{0.25, y}, {}, {}};
  Kinematics b{{0.25 + dx, -y}, {}, {}};
  ASSERT_NEAR(2.0 * r - length(b.p - a.p), 5e-6, 1e-9);
  ASSERT_LE(cushionSink(t, a.p, r), 1e-12);
  setApart(a, b, t, r);
  EXPECT_LE(2.0 * r - length(b.p - a.p), 0.5 * kTouchTolerance);
  EXPECT_LE(cushionSink(t, a.p, r), 1e-9);
  EXPECT_LE(cushionSink(t, b.p, r), 1e-9);
  EXPECT_NEAR(a.p.y, y, 1e-9);
  EXPECT_NEAR(b.p.y, -y, 1e-9);
}

}  // namespace
}  // namespace nineball::physics
