#include "nineball/fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace nineball {
namespace {

constexpr double kDegree = kPi / 180.0;

Scene caromShot(double heading_deg, double speed, Vec2 tip) {
  Scene s;
  s.table = TableDef::carom();
  s.physics = PhysicsParams::carom();
  s.balls = {BallState::at(0, {-0.6, -0.25}), BallState::at(1, {0.2, 0.05}),
             BallState::at(2, {0.9, 0.45})};
  Shot shot;
  shot.heading_rad = heading_deg * kDegree;
  shot.speed = speed;
  shot.tip = tip;
  s.shot = shot;
  return s;
}

TEST(Fit, RecoversTheShotOfASyntheticRecording) {
  const Scene truth = caromShot(19.0, 3.0, {0.2, 0.1});
  Tracker tracker;
  tracker.strike = 0.37;
  tracker.seed = 7;
  const Recording r = recordScene(truth, {"white", "yellow", "red"}, tracker);
  ASSERT_FALSE(recordingFault(r));
  FitOptions o;
  o.threads = 1;
  if (const char* e = std::getenv("EVALS")) o.evals = std::atoi(e);
  const ShotFit f = fitShot(r, o);
  const Shot& got = *f.scene.shot;
  std::printf(
      "heading %.4f speed %.4f tip %.3f %.3f elev %.3f strike %.4f full %.4f early %.4f evals %d\n",
      got.heading_rad / kDegree, got.speed, got.tip.x, got.tip.y, got.elevation_rad / kDegree,
      f.strike_time, f.rmse.full, f.rmse.early, f.evals);
  Scene at_truth = f.scene;
  at_truth.shot = truth.shot;
  const FitErrors e = fitErrors(r, at_truth, f.names, 0.37);
  std::printf("truth: full %.4f early %.4f\n", e.full, e.early);
  const FitErrors et = fitErrors(r, truth, f.names, 0.37);
  std::printf("exact truth: full %.4f early %.4f\n", et.full, et.early);
  EXPECT_NEAR(got.heading_rad / kDegree, 19.0, 0.1);
  EXPECT_NEAR(got.speed, 3.0, 0.03);
  EXPECT_NEAR(got.tip.x, 0.2, 0.05);
  EXPECT_NEAR(got.tip.y, 0.1, 0.05);
}

}  // namespace
}  // namespace nineball
