// The quick version of the numerical stability stress (the long one: nineball stress
// --layouts 3000 --long-run 3600). Every check must hold; and the checks must be able to
// fail, which a deliberately coarse world shows.
#include "nineball/stress.hpp"

#include <gtest/gtest.h>

TEST(Stress, QuickRunHasNoFailure) {
  nineball::StressOptions o;
  o.random_layouts = 100;
  o.long_run_s = 60.0;
  const nineball::StressReport r = nineball::runStress(o);
  EXPECT_GT(r.checks, 100000);
  EXPECT_EQ(r.failureCount(), 0);
  for (const std::string& f : r.first_failures) ADD_FAILURE() << f;
}

TEST(Stress, ChecksCatchACoarseWorld) {
  // At 1 Box2D unit per metre the slop is 5 mm: balls sink into cushions.
  nineball::StressOptions o;
  o.random_layouts = 20;
  o.long_run_s = 5.0;
  o.step.scale = 1.0;
  const nineball::StressReport r = nineball::runStress(o);
  EXPECT_GT(r.failures.count("not sunk into a cushion"), 0u);
}
