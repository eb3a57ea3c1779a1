// The quick version of the numerical stability stress (the long one: nineball stress
// --layouts 3000 --long-run 3600). Every check must hold; and the checks must be able to
// fail, which a deliberately coarse world shows.
#include "nineball/stress.hpp"

#include <gtest/gtest.h>

TEST(Stress, QuickRunHasNoFailure) {
  nineball::StressOptions o;
  o.random_layouts = 100;
  // random_settings keeps its default: 300 scenes with every setting drawn from its range.
  o.long_run_s = 60.0;
  const nineball::StressReport r = nineball::runStress(o);
  EXPECT_GT(r.checks, 100000);
  EXPECT_EQ(r.failureCount(), 0);
  for (const std::string& f : r.first_failures) ADD_FAILURE() << f;
}

TEST(Stress, ChecksCatchBox2DsOwnBallSolver) {
  // With Box2D's sequential solver resolving the frictionless e = 1 rack (contacts "box2d")
  // clusters gain energy: the checks must see it.
  nineball::StressOptions o;
  o.random_layouts = 20;
  o.random_settings = 0;
  o.long_run_s = 5.0;
  o.step.contacts = nineball::ContactModel::Box2D;
  const nineball::StressReport r = nineball::runStress(o);
  EXPECT_GT(r.failures.count("energy never rises"), 0u);
}

TEST(Stress, CushionSinkMeasuresHowDeepABallIsIn) {
  // Cushion events are exact now, so no setting sinks a ball: the depth is checked directly.
  const nineball::PhysicsParams p = nineball::PhysicsParams::real();
  const nineball::TableGeometry t = nineball::buildTable(nineball::TableDef{}, p.ball_radius);
  const double r = p.ball_radius, top = t.def.width / 2.0;
  EXPECT_NEAR(nineball::cushionSink(t, {0.3, top - r}, r), 0.0, 1e-12);
  EXPECT_NEAR(nineball::cushionSink(t, {0.3, top - r + 0.001}, r), 0.001, 1e-12);
  EXPECT_EQ(nineball::cushionSink(t, {0.3, 0.0}, r), 0.0);
}
