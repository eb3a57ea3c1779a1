// What a recording must be to be fitted (recordingFault), and what readRecording makes of one
// a real tracker writes: repeated times, samples a cue cannot explain.
#include "fit/recorded_shot.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fit/carom_shot.hpp"

namespace nineball {
namespace {

Recording oneBall(std::vector<double> t, std::vector<double> x, std::vector<double> y) {
  Recording r;
  r.table = TableDef::carom();
  r.physics = PhysicsParams::carom();
  RecordedPath white;
  white.name = "white";
  white.t = std::move(t);
  white.x = std::move(x);
  white.y = std::move(y);
  r.balls.push_back(white);
  return r;
}

// The synthetic three-cushion shot as a 50 Hz tracker records it, struck at 0.5 s.
Recording caromRecording(double noise = 0.005) {
  Tracker t;
  t.noise = noise;
  return recordScene(testing::caromShot(19.0, 3.0, {0.2, 0.1}), {"white", "yellow", "red"}, t);
}

// Every `every`th time of each ball written again for the sample after it (a coarse clock):
// the positions still differ.
void repeatTimes(Recording& r, std::size_t every) {
  for (RecordedPath& b : r.balls) {
    for (std::size_t i = every; i < b.t.size(); i += every) b.t[i] = b.t[i - 1];
  }
}

TEST(RecordingFault, AcceptsATimeRecordedTwice) {
  Recording r = caromRecording();
  repeatTimes(r, 7);
  EXPECT_EQ(recordingFault(r), std::nullopt);
}

TEST(RecordingFault, RefusesADecreasingTimeByName) {
  Recording r = caromRecording();
  r.balls[2].t[118] = r.balls[2].t[117] - 0.001;
  EXPECT_EQ(recordingFault(r), std::optional<std::string>("balls.red.t: decreasing at sample 118"));
}

TEST(RecordingFault, RefusesSamplesThatImplyMoreThanACueGives) {
  const Recording r = oneBall({0.0, 1e-200}, {-0.6, -0.5994}, {0.0, 0.0});
  EXPECT_EQ(recordingFault(r),
            std::optional<std::string>("balls.white: samples 0-1 imply 6e+196 m/s"));
  // 12 m/s is a hard break: 13 m/s between frames is no shot.
  const Recording fast = oneBall({0.0, 0.02, 0.04}, {0.0, 0.2, 0.46}, {0.0, 0.0, 0.0});
  EXPECT_EQ(recordingFault(fast),
            std::optional<std::string>("balls.white: samples 1-2 imply 13 m/s"));
  const Recording hard = oneBall({0.0, 0.02, 0.04}, {0.0, 0.2, 0.43}, {0.0, 0.0, 0.0});
  EXPECT_EQ(recordingFault(hard), std::nullopt);
}

TEST(RecordingFault, SkipsThePairsAtOneTimeWhoseSpeedIsNotDefined) {
  const Recording r = oneBall({0.0, 0.02, 0.02, 0.04}, {0.0, 0.01, 0.05, 0.06}, {0, 0, 0, 0});
  EXPECT_EQ(recordingFault(r), std::nullopt);
  const Recording still = oneBall({0.5, 0.5, 0.5}, {0.0, 0.01, 0.02}, {0.0, 0.0, 0.0});
  EXPECT_EQ(recordingFault(still),
            std::optional<std::string>(
                "balls.white.t: every sample at one time (needs two different times at least)"));
}

TEST(RecordingFault, RefusesARecordingLongerThanARunMayLast) {
  Recording r = caromRecording();
  r.balls[2].t.back() = 1e6;
  EXPECT_EQ(
      recordingFault(r),
      std::optional<std::string>("balls.red.t: sample " + std::to_string(r.balls[2].t.size() - 1) +
                                 " lies 1e+06 s after the recording's first, more than "
                                 "the 3600 s a run may last"));
}

// The first guess of the strike is a legal, finite shot whatever the clock did at the cue
// ball's first move.
void expectALegalFirstGuess(const Recording& r) {
  ASSERT_EQ(recordingFault(r), std::nullopt);
  const fit::RecordedShot s = fit::readRecording(r);
  EXPECT_TRUE(std::isfinite(s.speed));
  EXPECT_GE(s.speed, fit::kMinSpeed);
  EXPECT_LE(s.speed, fit::kMaxSpeed);
  EXPECT_TRUE(std::isfinite(s.heading));
  EXPECT_TRUE(std::isfinite(s.strike));
  EXPECT_LE(s.earliest, s.strike);
  EXPECT_LE(s.strike, s.latest);
  EXPECT_LT(s.cue_onset, s.first_event);
  for (const Vec2& p : s.rest) EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
}

TEST(ReadRecording, GuessesALegalStrikeFromRepeatedTimes) {
  Recording r = caromRecording();
  // The cue ball's first samples in motion (the strike at 0.5 s, frames every 0.02 s) share
  // their times in pairs.
  RecordedPath& white = r.balls[0];
  for (std::size_t i = 26; i < 34; i += 2) white.t[i] = white.t[i - 1];
  expectALegalFirstGuess(r);
  const fit::RecordedShot s = fit::readRecording(r);
  EXPECT_NEAR(s.heading, 19.0 * kPi / 180.0, 0.1);
  EXPECT_NEAR(s.strike, 0.5, 0.05);
}

TEST(ReadRecording, GuessesALegalStrikeFromSamplesAnInstantApart) {
  // Two samples 1e-160 s apart at one place (the squared interval underflows) and the last
  // two at one time.
  expectALegalFirstGuess(oneBall({0.0, 1e-160}, {-0.6, -0.6}, {0.0, 0.0}));
  expectALegalFirstGuess(oneBall({0.0, 0.02, 0.04, 0.04}, {-0.6, -0.5, -0.4, -0.39}, {0, 0, 0, 0}));
}

}  // namespace
}  // namespace nineball
