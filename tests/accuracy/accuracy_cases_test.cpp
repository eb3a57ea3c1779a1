// The canonical cases `nineball bench` sweeps: at the default step settings every one meets
// its target (the issues' tolerances, stated in runAccuracyCases). Once the real preset's
// friction and cushion reached these paper-formula cases unnoticed; this fails if they do.
#include <gtest/gtest.h>

#include <cstdio>

#include "accuracy/accuracy.hpp"

namespace nineball {
namespace {

TEST(AccuracyCases, EveryCaseMeetsItsTargetAtTheDefaults) {
  for (const CaseError& e : runAccuracyCases(StepParams{})) {
    std::printf("[ measured ] %-13s %.3g %s (target %.3g)\n", e.name.c_str(), e.worst,
                e.unit.c_str(), e.target);
    EXPECT_LE(e.score(), 1.0) << e.name << ": " << e.worst << " " << e.unit;
  }
}

}  // namespace
}  // namespace nineball
