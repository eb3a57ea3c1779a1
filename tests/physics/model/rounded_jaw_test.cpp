// The snooker tables and their rounded jaws (knuckles): the geometry the table builds, and the
// contact search meeting a knuckle as the arc it is, not as the chords that draw it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "nineball/params.hpp"
#include "nineball/table.hpp"
#include "physics/model/contact_times.hpp"
#include "physics/resolve/ball_ball/collide.hpp"

namespace nineball::physics {
namespace {

const double kR = PhysicsParams::snooker().ball_radius;

TEST(SnookerTable, IsNamedAfterPoolsAndCaromsTables) {
  const std::vector<std::string> names = TableDef::names();
  ASSERT_GE(names.size(), 7u);
  EXPECT_EQ(names[0], "9ft");
  EXPECT_EQ(names[3], "carom");
  EXPECT_EQ(names[names.size() - 2], "snooker");
  EXPECT_EQ(names.back(), "snooker-10ft");
  const TableDef full = *TableDef::named("snooker");
  EXPECT_DOUBLE_EQ(full.length, 3.569);
  EXPECT_DOUBLE_EQ(full.width, 1.778);
  const TableDef ten = *TableDef::named("snooker-10ft");
  EXPECT_NEAR(ten.length, 3.569 * 10.0 / 12.0, 1e-12);
  EXPECT_NEAR(ten.width / ten.length, full.width / full.length, 1e-12);
  EXPECT_NEAR(ten.corner_jaw_radius, full.corner_jaw_radius * 10.0 / 12.0, 1e-12);
  EXPECT_EQ(ten.corner_jaw_deg, full.corner_jaw_deg);
  EXPECT_FALSE(checkTable(full, kR)) << *checkTable(full, kR);
  EXPECT_FALSE(checkTable(ten, kR)) << *checkTable(ten, kR);
}

TEST(SnookerTable, PoolTablesHaveSharpJawsAndNoArcs) {
  for (const char* name : {"9ft", "8ft", "7ft", "carom"}) {
    const TableGeometry t = buildTable(*TableDef::named(name), 0.028575);
    EXPECT_TRUE(t.arcs.empty()) << name;
    for (const Pocket& p : t.pockets) {
      EXPECT_EQ(p.nose_a, p.jaw_a) << name;
      EXPECT_EQ(p.nose_b, p.jaw_b) << name;
    }
    EXPECT_TRUE(Cushions::of(t).arcs.empty()) << name;
  }
}

TEST(SnookerTable, EveryJawTurnsIntoItsPocketThroughAKnuckleTangentToNoseAndJaw) {
  const TableDef def = TableDef::snooker();
  const TableGeometry t = buildTable(def, kR);
  ASSERT_EQ(t.arcs.size(), 12u);  // two knuckles a pocket
  const auto& loop = t.cushion_loop;
  for (const CushionArc& arc : t.arcs) {
    const bool corner = std::abs(arc.radius - def.corner_jaw_radius) < 1e-15;
    EXPECT_TRUE(corner || std::abs(arc.radius - def.side_jaw_radius) < 1e-15);
    EXPECT_EQ(loop[arc.first], arc.start);
    EXPECT_EQ(loop[arc.last], arc.end);
    // Every vertex on the arc, every chord within the stated error behind it.
    for (std::size_t k = arc.first; k <= arc.last; ++k) {
      EXPECT_NEAR(length(loop[k] - arc.centre), arc.radius, 1e-12);
      if (k == arc.last) continue;
      const Vec2 mid = (loop[k] + loop[k + 1]) * 0.5;
      EXPECT_LE(arc.radius - length(mid - arc.centre), kArcChordError * (1.0 + 1e-6));
      EXPECT_GT(arc.radius - length(mid - arc.centre), 0.0);  // behind the arc: a knuckle
    }
    // Tangent at both ends: the straight piece before and after runs square to the radius.
    const std::size_t n = loop.size();
    const Vec2 before = normalized(loop[arc.first] - loop[(arc.first + n - 1) % n]);
    const Vec2 after = normalized(loop[(arc.last + 1) % n] - loop[arc.last]);
    EXPECT_NEAR(dot(before, normalized(arc.start - arc.centre)), 0.0, 1e-9);
    EXPECT_NEAR(dot(after, normalized(arc.end - arc.centre)), 0.0, 1e-9);
    // The turn: the jaw's angle to the nose.
    const double turn = std::acos(std::clamp(dot(before, after), -1.0, 1.0));
    EXPECT_NEAR(turn, degToRad(180.0 - (corner ? def.corner_jaw_deg : def.side_jaw_deg)), 1e-9);
    // Convex: the centre lies outside the table, the arc bulges into it.
    EXPECT_FALSE(t.insideLoop(arc.centre));
  }
}

TEST(SnookerTable, NosesAndPocketOutlinesMeetWhereTheKnucklesBegin) {
  const TableGeometry t = buildTable(TableDef::snooker(), kR);
  const auto noses = cushionNoses(t);
  ASSERT_EQ(noses.size(), 6u);
  for (std::size_t i = 0; i < t.pockets.size(); ++i) {
    const Pocket& p = t.pockets[i];
    EXPECT_NE(p.nose_a, p.jaw_a);
    EXPECT_EQ(noses[(i + 5) % 6].second, p.nose_a);
    EXPECT_EQ(noses[i].first, p.nose_b);
    const std::vector<Vec2> outline = pocketOutline(t, p);
    ASSERT_GT(outline.size(), 40u);  // the knuckles drawn finely
    EXPECT_EQ(outline.front(), p.nose_a);
    EXPECT_EQ(outline.back(), p.nose_b);
  }
  // The cushion noses stay on the cushion lines: the knuckles leave the rails straight.
  for (const auto& [a, b] : noses) {
    EXPECT_TRUE(std::abs(a.x - b.x) < 1e-12 || std::abs(a.y - b.y) < 1e-12);
  }
}

// The knuckle of the top-left pocket on the top rail: walking clockwise, the pocket's second
// arc, from its jaw face out onto the rail (it ends where the rail begins).
CushionArc topLeftOnTopRail(const TableGeometry& t) {
  return t.arcs[1];
}

Vec2 middleNormal(const CushionArc& arc) {
  return normalized(normalized(arc.start - arc.centre) + normalized(arc.end - arc.centre));
}

TEST(KnuckleContact, IsMetAtRPlusRhoFromItsCentreAlongTheArcNormal) {
  const TableGeometry t = buildTable(TableDef::snooker(), kR);
  const Cushions cushions = Cushions::of(t);
  EXPECT_EQ(cushions.arcs.size(), 12u);
  const CushionArc arc = topLeftOnTopRail(t);
  const Vec2 n = middleNormal(arc);
  const Vec2 touch = arc.centre + n * (kR + arc.radius);
  // Head on, along the normal, from 0.2 m out, at 2 m/s without friction: met at s = 0.1.
  const Path path{touch + n * 0.2, n * -2.0, {}};
  const auto hit = cushionContact(path, kR, cushions, 1.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->s, 0.1, 1e-12);
  EXPECT_NEAR(hit->normal.x, n.x, 1e-12);
  EXPECT_NEAR(hit->normal.y, n.y, 1e-12);
  // The chords would have let it in further: the arc is met first, by up to the chord error.
  const std::vector<Vec2> normals = touchingNormals(touch, kR, cushions);
  ASSERT_EQ(normals.size(), 1u);
  EXPECT_NEAR(dot(normals[0], n), 1.0, 1e-12);
}

TEST(KnuckleContact, AGlancingPathIsMetWhereItFirstTouchesTheArc) {
  const TableGeometry t = buildTable(TableDef::snooker(), kR);
  const Cushions cushions = Cushions::of(t);
  const CushionArc arc = topLeftOnTopRail(t);
  const Vec2 n = middleNormal(arc);
  const Vec2 along{-n.y, n.x};
  // A straight path aimed beside the centre, at a point 0.3 (R + rho) off it: it meets the
  // circle of R + rho off the normal, and is met there with the radial normal.
  const double reach = kR + arc.radius, h = 0.3 * reach;
  const Vec2 start = arc.centre + n * reach * 2.0;
  const Vec2 dir = normalized(arc.centre + along * h - start);
  const Path path{start, dir * 1.5, {}};
  const auto hit = cushionContact(path, kR, cushions, 1.0);
  ASSERT_TRUE(hit);
  const Vec2 at = path.at(hit->s);
  EXPECT_NEAR(length(at - arc.centre), reach, 1e-12);
  EXPECT_NEAR(dot(hit->normal, normalized(at - arc.centre)), 1.0, 1e-12);
  EXPECT_TRUE(arc.covers(hit->normal));
}

TEST(KnuckleContact, OutsideItsSpanTheArcGivesWayToTheNose) {
  const TableGeometry t = buildTable(TableDef::snooker(), kR);
  const Cushions cushions = Cushions::of(t);
  const CushionArc arc = topLeftOnTopRail(t);
  // Straight down onto the top rail just past the knuckle's start: the rail, not the arc.
  const Vec2 on_rail = arc.end + Vec2{0.01, 0.0};
  const Path path{on_rail + Vec2{0.0, -kR - 0.1}, {0.0, 1.0}, {}};
  const auto hit = cushionContact(path, kR, cushions, 1.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->s, 0.1, 1e-12);
  EXPECT_NEAR(hit->normal.y, -1.0, 1e-15);
}

TEST(KnuckleContact, TheGridFindsWhatTheFullSearchFinds) {
  const TableGeometry t = buildTable(TableDef::snooker(), kR);
  const Cushions cushions = Cushions::of(t);
  Cushions everything = cushions;
  everything.grid_nx = 0;  // no cell: every search looks at every piece
  everything.grid_ny = 0;
  for (const CushionArc& arc : t.arcs) {
    for (double f : {0.1, 0.5, 0.9}) {
      const Vec2 d = normalized(normalized(arc.start - arc.centre) * (1.0 - f) +
                                normalized(arc.end - arc.centre) * f);
      const Path path{arc.centre + d * (kR + arc.radius + 0.02), d * -0.5, {}};
      const auto a = cushionContact(path, kR, cushions, 0.1);
      const auto b = cushionContact(path, kR, everything, 0.1);
      ASSERT_TRUE(a && b);
      EXPECT_EQ(a->s, b->s);
      EXPECT_NEAR(a->s, 0.04, 1e-12);
    }
  }
}

TEST(KnuckleGeometry, SinkAndLiftAreMeasuredFromTheArcNotItsChords) {
  const TableGeometry t = buildTable(TableDef::snooker(), kR);
  const CushionArc arc = topLeftOnTopRail(t);
  // Between two sample points, where a chord lies furthest behind the arc.
  const auto& loop = t.cushion_loop;
  const Vec2 d = normalized((loop[arc.first] + loop[arc.first + 1]) * 0.5 - arc.centre);
  const Vec2 pressed = arc.centre + d * (kR + arc.radius - 1e-4);
  EXPECT_NEAR(cushionSink(t, pressed, kR), 1e-4, 1e-12);
  EXPECT_FALSE(t.ballFits(pressed, kR));
  const Vec2 lifted = outOfCushions(t, pressed, kR);
  EXPECT_NEAR(length(lifted - arc.centre), kR + arc.radius, 1e-12);
  EXPECT_TRUE(t.ballFits(arc.centre + d * (kR + arc.radius), kR));
}

TEST(KnuckleGeometry, CheckTableRefusesAKnuckleLongerThanItsJaw) {
  TableDef def = TableDef::snooker();
  def.corner_jaw_radius = 0.5;
  const auto problem = checkTable(def, kR);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("knuckle"), std::string::npos) << *problem;
  def = TableDef::snooker();
  def.side_jaw_radius = -0.01;
  ASSERT_TRUE(checkTable(def, kR));
}

}  // namespace
}  // namespace nineball::physics
