// Calibration: the same physics scores the same whenever it is tried, and the calibrated values
// come with standard errors, correlations and a convergence flag that a paper can quote.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "fit/calibration_stats.hpp"
#include "fit/carom_shot.hpp"
#include "fit/physics_scorer.hpp"
#include "fit/recorded_shot.hpp"
#include "nineball/fit.hpp"

namespace nineball {
namespace {

// A carom table whose cloth rolls 20 % heavier than the preset its recordings claim.
constexpr double kTrueRolling = 0.006;

std::optional<PhysicsParams> setRolling(const PhysicsParams& base, const std::vector<double>& v,
                                        std::string&) {
  if (!(v[0] >= 0.0)) return std::nullopt;
  PhysicsParams p = base;
  p.rolling_friction = v[0];
  return p;
}

std::vector<Recording> heavierCloth(std::size_t count) {
  struct Stroke {
    double heading_deg, speed;
    Vec2 tip;
  };
  const Stroke strokes[] = {{19.0, 3.0, {0.2, 0.1}},   {12.0, 2.5, {-0.2, -0.2}},
                            {22.0, 4.0, {0.3, -0.1}},  {16.0, 2.0, {0.0, 0.0}},
                            {25.0, 3.5, {-0.1, -0.3}}, {40.0, 3.0, {0.1, 0.0}}};
  std::vector<Recording> shots;
  for (std::size_t k = 0; k < count; ++k) {
    const Stroke& s = strokes[k % std::size(strokes)];
    Scene scene = testing::caromShot(s.heading_deg, s.speed, s.tip);
    scene.physics.rolling_friction = kTrueRolling;
    Tracker tracker;
    tracker.strike = 0.8;
    tracker.seed = 200 + k;
    Recording r =
        recordScene(scene, {"white", "yellow", "red"}, tracker, "shot-" + std::to_string(k));
    r.physics = PhysicsParams::carom();
    shots.push_back(r);
  }
  return shots;
}

CalibrateOptions rollingOnly() {
  CalibrateOptions o;
  o.params = {"rolling_friction"};
  o.start = {PhysicsParams::carom().rolling_friction};
  o.set = &setRolling;
  o.holdout = 0.0;
  o.evals = 600;
  o.refit_evals = 60;
  o.candidates = 9;
  return o;
}

// Every physics the progress lines report ("candidate 7 (0.0059): median 0.00775 m", "candidate
// 7 again (...)"), with each median it was reported with. Read by hand: GCC 12's std::regex
// trips -Wmaybe-uninitialized in the sanitizer build.
std::map<std::string, std::vector<std::string>> mediansByPhysics(
    const std::vector<std::string>& lines) {
  const std::string head = "candidate ";
  const std::string middle = "): median ";
  std::map<std::string, std::vector<std::string>> out;
  for (const std::string& line : lines) {
    if (line.compare(0, head.size(), head) != 0) continue;
    const std::size_t open = line.find(" (");
    const std::size_t close = line.rfind(middle);
    if (open == std::string::npos || close == std::string::npos || close < open) continue;
    if (line.size() < 2 || line.compare(line.size() - 2, 2, " m") != 0) continue;
    const std::size_t from = close + middle.size();
    out[line.substr(open + 2, close - open - 2)].push_back(
        line.substr(from, line.size() - 2 - from));
  }
  return out;
}

TEST(Calibrate, ScoresAPhysicsTheSameInEveryRoundThatTriesIt) {
  // Each round after the first begins at the last one's best: the same physics, tried again.
  const std::vector<Recording> shots = heavierCloth(3);
  CalibrateOptions o = rollingOnly();
  std::vector<std::string> lines;
  o.progress = [&](const std::string& line) { lines.push_back(line); };
  calibrate(shots, o);
  std::size_t repeated = 0;
  for (const auto& [physics, medians] : mediansByPhysics(lines)) {
    for (const std::string& m : medians) EXPECT_EQ(m, medians.front()) << physics;
    repeated += medians.size() > 1;
  }
  EXPECT_GT(repeated, 0u) << "no physics was tried twice: the test tests nothing";
}

// The training shots read and fitted under the recordings' physics, as calibrate does.
struct Prepared {
  std::vector<fit::RecordedShot> read;
  std::vector<fit::Found> first;

  std::vector<const fit::RecordedShot*> pointers() const {
    std::vector<const fit::RecordedShot*> out;
    for (const fit::RecordedShot& s : read) out.push_back(&s);
    return out;
  }
};

Prepared prepared(const std::vector<Recording>& shots, int evals) {
  Prepared p;
  for (const Recording& r : shots) {
    p.read.push_back(fit::readRecording(r));
    fit::separate(p.read.back().rest, r.table, r.physics.ball_radius);
  }
  for (std::size_t i = 0; i < shots.size(); ++i) {
    p.first.push_back(
        fit::searchShot(p.read[i], shots[i].physics, evals, FitObjective::Full, 1 + i, nullptr));
  }
  return p;
}

fit::PhysicsScorer::Settings scorerSettings(int threads) {
  fit::PhysicsScorer::Settings s;
  s.base = PhysicsParams::carom();
  s.set = &setRolling;
  s.refit_evals = 40;
  s.threads = threads;
  return s;
}

TEST(PhysicsScorer, ScoresAPhysicsAloneAsAfterOthersAndOnAnyThreads) {
  const std::vector<Recording> shots = heavierCloth(2);
  const Prepared p = prepared(shots, 400);
  const std::vector<double> probe{0.0057};
  fit::PhysicsScorer alone(p.pointers(), p.first, scorerSettings(1));
  const ScoredPhysics first = alone.score(probe);
  // Others first (a refit that started warm from them would end elsewhere), on two threads.
  fit::PhysicsScorer after(p.pointers(), p.first, scorerSettings(2));
  after.score({0.0066});
  after.score({0.0051});
  const ScoredPhysics later = after.score(probe);
  EXPECT_EQ(later.errors, first.errors);
  EXPECT_EQ(later.median, first.median);
  EXPECT_TRUE(after.scored(probe));
  EXPECT_EQ(after.numberOf(probe), 3u);
  EXPECT_EQ(after.tried().size(), 3u);
}

void expectAProperCorrelation(const CalibrationUncertainty& u, std::size_t n) {
  ASSERT_EQ(u.correlation.size(), n);
  for (std::size_t j = 0; j < n; ++j) {
    ASSERT_EQ(u.correlation[j].size(), n);
    EXPECT_EQ(u.correlation[j][j], 1.0);
    for (std::size_t k = 0; k < n; ++k) {
      EXPECT_EQ(u.correlation[j][k].has_value(), u.correlation[k][j].has_value());
      if (!u.correlation[j][k]) continue;
      EXPECT_EQ(*u.correlation[j][k], *u.correlation[k][j]);
      EXPECT_LE(std::abs(*u.correlation[j][k]), 1.0 + 1e-12);
    }
  }
}

TEST(Calibrate, TheTrueValueLiesWithinThreeStandardErrors) {
  const std::vector<Recording> shots = heavierCloth(6);
  CalibrateOptions o = rollingOnly();
  o.candidates = 14;
  const Calibration c = calibrate(shots, o);
  ASSERT_EQ(c.uncertainty.stderrs.size(), 1u);
  ASSERT_TRUE(c.uncertainty.stderrs[0]) << c.uncertainty.why_not;
  const double error = *c.uncertainty.stderrs[0];
  std::printf("rolling %.6f +- %.6f (truth %.4f); %s\n", c.values[0], error, kTrueRolling,
              c.convergence.c_str());
  EXPECT_TRUE(std::isfinite(error));
  EXPECT_GT(error, 0.0);
  EXPECT_LT(std::abs(c.values[0] - kTrueRolling), 3.0 * error);
  EXPECT_EQ(c.uncertainty.method, "bootstrap over shots");
  EXPECT_EQ(c.uncertainty.resamples, 200);
  EXPECT_TRUE(c.uncertainty.why_not.empty());
  expectAProperCorrelation(c.uncertainty, 1);
  EXPECT_FALSE(c.convergence.empty());
}

TEST(Calibrate, ReportsTheSameUncertaintyForTheSameSeed) {
  const std::vector<Recording> shots = heavierCloth(3);
  CalibrateOptions o = rollingOnly();
  o.threads = 1;
  const Calibration one = calibrate(shots, o);
  o.threads = 2;
  const Calibration two = calibrate(shots, o);
  EXPECT_EQ(one.values, two.values);
  EXPECT_EQ(one.uncertainty.stderrs, two.uncertainty.stderrs);
  EXPECT_EQ(one.converged, two.converged);
  EXPECT_EQ(one.convergence, two.convergence);
}

std::optional<PhysicsParams> setRollingAndPocket(const PhysicsParams& base,
                                                 const std::vector<double>& v, std::string&) {
  if (!(v[0] >= 0.0 && v[1] >= 0.0 && v[1] <= 1.0)) return std::nullopt;
  PhysicsParams p = base;
  p.rolling_friction = v[0];
  p.pocket_restitution = v[1];
  return p;
}

TEST(Calibrate, LeavesAParameterTheShotsDoNotFeelWithoutAStandardError) {
  // A carom table has no pockets: whatever the back of a pocket does, no shot can tell.
  const std::vector<Recording> shots = heavierCloth(3);
  CalibrateOptions o = rollingOnly();
  o.params = {"rolling_friction", "pocket_restitution"};
  o.start = {PhysicsParams::carom().rolling_friction, PhysicsParams::carom().pocket_restitution};
  o.set = &setRollingAndPocket;
  o.candidates = 12;
  const Calibration c = calibrate(shots, o);
  EXPECT_FALSE(c.uncertainty.stderrs[1]);
  EXPECT_FALSE(c.converged);
  EXPECT_NE(c.convergence.find("pocket_restitution: the median does not tell its values apart"),
            std::string::npos)
      << c.convergence;
  expectAProperCorrelation(c.uncertainty, 2);
  EXPECT_FALSE(c.uncertainty.correlation[0][1]);
}

// A physics scored with per-shot errors that make a bowl about `centre` in each parameter.
ScoredPhysics bowlAt(const std::vector<double>& x, const std::vector<double>& centre,
                     const std::vector<double>& curvature, const std::vector<double>& tilts) {
  ScoredPhysics s;
  s.values = x;
  for (double tilt : tilts) {
    double e = 0.01;
    for (std::size_t k = 0; k < x.size(); ++k) {
      const double d = x[k] - centre[k] - tilt;
      e += curvature[k] * d * d;
    }
    s.errors.push_back(e);
  }
  s.median = fit::median(s.errors);
  return s;
}

std::vector<ScoredPhysics> gridOf(const std::vector<double>& curvature,
                                  const std::vector<double>& tilts) {
  std::vector<ScoredPhysics> tried;
  for (int i = -8; i <= 8; ++i) {
    for (int j = -8; j <= 8; ++j) {
      tried.push_back(bowlAt({0.01 * i, 0.01 * j}, {0.0, 0.0}, curvature, tilts));
    }
  }
  return tried;
}

fit::BootstrapInput bowlInput(std::vector<ScoredPhysics> tried) {
  fit::BootstrapInput in;
  in.tried = std::move(tried);
  in.best = {0.0, 0.0};
  in.scale = {0.01, 0.01};
  in.names = {"a", "b"};
  return in;
}

TEST(CalibrationStats, ShotsThatDisagreeGiveASpreadAndAgreeingOnesNone) {
  // Each shot's own best lies a little off the common one: the resamples move the minimum.
  const std::vector<double> tilts{-0.05, -0.02, 0.0, 0.01, 0.03, 0.04, -0.01};
  const CalibrationUncertainty u = fit::bootstrapOverShots(bowlInput(gridOf({1.0, 4.0}, tilts)));
  ASSERT_TRUE(u.stderrs[0] && u.stderrs[1]) << u.why_not;
  EXPECT_GT(*u.stderrs[0], 0.0);
  EXPECT_LT(*u.stderrs[0], 0.05);
  expectAProperCorrelation(u, 2);
  // Every shot agrees exactly: no spread, so no standard error, and why.
  const CalibrationUncertainty none =
      fit::bootstrapOverShots(bowlInput(gridOf({1.0, 4.0}, {0.0, 0.0, 0.0})));
  EXPECT_FALSE(none.stderrs[0]);
  EXPECT_NE(none.why_not.find("the same physics was best in every resample"), std::string::npos)
      << none.why_not;
}

TEST(CalibrationStats, AParameterTheMedianDoesNotFeelHasNoStandardError) {
  const std::vector<double> tilts{-0.05, -0.02, 0.0, 0.01, 0.03, 0.04, -0.01};
  const CalibrationUncertainty u = fit::bootstrapOverShots(bowlInput(gridOf({1.0, 0.0}, tilts)));
  EXPECT_TRUE(u.stderrs[0]) << u.why_not;
  EXPECT_FALSE(u.stderrs[1]);
  EXPECT_NE(u.why_not.find("b: the median does not tell its values apart"), std::string::npos)
      << u.why_not;
  expectAProperCorrelation(u, 2);
  EXPECT_FALSE(u.correlation[0][1]);
}

}  // namespace
}  // namespace nineball
