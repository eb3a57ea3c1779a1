// The warnings and unreproduced balls of a fit (src/fit/fit_warnings.cpp): each from a
// synthetic recording (recordScene) edited as a real tracker spoils one, reviewed against the
// shot that made it (reviewFit), or fitted (fitShot).
#include <gtest/gtest.h>

#include <algorithm>

#include "fit/carom_shot.hpp"
#include "nineball/fit.hpp"

namespace nineball {
namespace {

const std::vector<std::string> kNames{"white", "yellow", "red"};
constexpr double kStrike = 0.5;
// The review's budget: its convergence check searches a few % of it, at least two simplexes.
constexpr int kEvals = 400;

Scene truth() {
  return testing::caromShot(19.0, 3.0, {0.2, 0.1});
}

Recording recorded(double noise = 0.005) {
  Tracker t;
  t.noise = noise;
  t.strike = kStrike;
  return recordScene(truth(), kNames, t);
}

// The shot that made the recording, as a fit of it.
ShotFit fitOfTheTruth(const Recording& r, const Scene& scene = truth()) {
  ShotFit f;
  f.id = r.id;
  f.scene = scene;
  f.names = kNames;
  f.strike_time = kStrike;
  f.rmse = fitErrors(r, scene, kNames, kStrike);
  return f;
}

ShotFit reviewed(const Recording& r, ShotFit f) {
  EXPECT_EQ(recordingFault(r), std::nullopt);
  reviewFit(r, r.physics, f, kEvals, FitObjective::Full);
  return f;
}

bool has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(FitWarnings, NoneForTheShotThatMadeANoiselessRecording) {
  const Recording r = recorded(0.0);
  const ShotFit f = reviewed(r, fitOfTheTruth(r));
  EXPECT_EQ(f.warnings, std::vector<std::string>{});
  EXPECT_EQ(f.unreproduced, std::vector<std::string>{});
}

TEST(FitWarnings, NothingMovesWhenEveryBallStaysWhereItStood) {
  Recording r = recorded();
  for (RecordedPath& b : r.balls) {
    std::fill(b.x.begin(), b.x.end(), b.x.front());
    std::fill(b.y.begin(), b.y.end(), b.y.front());
  }
  const ShotFit f = reviewed(r, fitOfTheTruth(r));
  EXPECT_TRUE(has(f.warnings, "nothing moves")) << ::testing::PrintToString(f.warnings);
  // The shot moves all three, the recording none.
  EXPECT_EQ(f.unreproduced, kNames);
}

TEST(FitWarnings, TwoBallsTrackedAtOnePlace) {
  Recording r = recorded();
  // The tracker followed yellow twice and red not at all.
  r.balls[2].t = r.balls[1].t;
  r.balls[2].x = r.balls[1].x;
  r.balls[2].y = r.balls[1].y;
  for (double& x : r.balls[2].x) x += 0.001;
  const ShotFit f = reviewed(r, fitOfTheTruth(r));
  EXPECT_TRUE(has(f.warnings, "balls yellow and red tracked at one place"))
      << ::testing::PrintToString(f.warnings);
  EXPECT_FALSE(has(f.warnings, "balls white and yellow tracked at one place"));
}

TEST(FitWarnings, RecordingStartsAfterTheStrike) {
  Recording r = recorded();
  // The recording begins two frames after the strike.
  for (RecordedPath& b : r.balls) {
    const auto first = std::find_if(b.t.begin(), b.t.end(), [](double t) { return t > 0.53; });
    const auto drop = first - b.t.begin();
    b.t.erase(b.t.begin(), first);
    b.x.erase(b.x.begin(), b.x.begin() + drop);
    b.y.erase(b.y.begin(), b.y.begin() + drop);
  }
  FitOptions o;
  o.evals = 300;
  o.threads = 1;
  const ShotFit f = fitShot(r, o);
  EXPECT_TRUE(has(f.warnings, "recording starts after the strike"))
      << ::testing::PrintToString(f.warnings);
}

TEST(FitWarnings, DidNotConvergeWhenAShortSearchStillLowersTheError) {
  const Recording r = recorded();
  Scene off = truth();
  off.shot->heading_rad += 0.5 * kPi / 180.0;
  const ShotFit f = reviewed(r, fitOfTheTruth(r, off));
  EXPECT_TRUE(has(f.warnings, "did not converge")) << ::testing::PrintToString(f.warnings);
}

TEST(FitWarnings, UnreproducedAreTheBallsThatMoveInTheRecordingOrTheFitAlone) {
  Recording r = recorded();
  // Red stands still in the recording; the shot sends yellow into it.
  RecordedPath& red = r.balls[2];
  std::fill(red.x.begin(), red.x.end(), red.x.front());
  std::fill(red.y.begin(), red.y.end(), red.y.front());
  ShotFit f = reviewed(r, fitOfTheTruth(r));
  EXPECT_EQ(f.unreproduced, std::vector<std::string>{"red"});
  // A shot too soft to move anything: every ball the recording moves is unreproduced.
  Scene soft = truth();
  soft.shot->speed = 0.05;
  f = reviewed(recorded(), fitOfTheTruth(recorded(), soft));
  EXPECT_EQ(f.unreproduced, kNames);
}

}  // namespace
}  // namespace nineball
