// Whole shots, cue strike to rest: the Box2D engine at its default settings against the
// reference engine (exact, event-based, no Box2D). The issue "Whole shots exact" asks for the
// same events, final positions within 1 mm (worst case) and event times within 1 ms, and for
// the break's first 15 events the same and each within 1 ms (the constants and where they
// come from: nineball/whole_shots.hpp). The suite's coverage is asserted so that it cannot
// pass on an empty or one-sided set of shots, and the comparison is shown to fail where it
// must.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <string>

#include "accuracy/whole_shots.hpp"
#include "nineball/scenes.hpp"

using namespace nineball;

namespace {

// Shots of each cushion count the suite must hold: "at least a few".
constexpr int kShotsPerCushionCount = 3;

const WholeShotReport& defaultReport() {
  static const WholeShotReport report = compareWholeShots(StepParams{});
  return report;
}

std::string describe(const WholeShotResult& s) {
  return "shot " + std::to_string(s.index) + " (" + s.preset + ", " + spinKindName(s.spin) + ", " +
         std::to_string(s.balls) + " balls, " + std::to_string(s.cushions) + " cushions, " +
         std::to_string(s.speed) + " m/s)";
}

}  // namespace

TEST(WholeShots, SuiteCoversBallsCushionsPresetsAndSpin) {
  const std::vector<Scene> scenes = wholeShotScenes();
  ASSERT_GE(scenes.size(), 40u);
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const Scene& s = scenes[i];
    EXPECT_FALSE(validateScene(s)) << "shot " << i << ": " << *validateScene(s);
    ASSERT_TRUE(s.shot) << i;
    EXPECT_FALSE(s.until) << i << ": not until rest";
    EXPECT_EQ(s.table.length, TableDef{}.length) << i;
    EXPECT_EQ(s.table.width, TableDef{}.width) << i;
    EXPECT_GE(s.shot->speed, 0.3) << i;
    EXPECT_LE(s.shot->speed, 8.0) << i;
    EXPECT_LE(length(s.shot->tip), 0.5) << i;
    if (!s.physics.spin()) {
      EXPECT_EQ(s.shot->tip, Vec2{}) << i << ": the paper preset has no spin";
    }
  }
  // The same list every time it is asked for.
  const std::vector<Scene> again = wholeShotScenes();
  ASSERT_EQ(again.size(), scenes.size());
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    EXPECT_EQ(again[i].shot->heading_rad, scenes[i].shot->heading_rad) << i;
    EXPECT_EQ(again[i].balls.size(), scenes[i].balls.size()) << i;
  }

  std::map<int, int> balls, cushions;
  std::map<std::string, int> presets, spins;
  for (const WholeShotResult& s : defaultReport().shots) {
    ++balls[s.balls];
    ++cushions[s.cushions];
    ++presets[s.preset];
    if (s.preset == "real") ++spins[spinKindName(s.spin)];
  }
  for (int n = 1; n <= 4; ++n) EXPECT_GT(balls[n], 0) << n << " balls";
  for (int c = 0; c <= 6; ++c) EXPECT_GE(cushions[c], kShotsPerCushionCount) << c << " cushions";
  EXPECT_EQ(balls.size(), 4u) << "only 1-4 balls";
  EXPECT_EQ(cushions.size(), 7u) << "only 0-6 cushions";
  EXPECT_GT(presets["real"], 0);
  EXPECT_GT(presets["paper"], 0);
  for (const char* kind : {"stun", "follow", "draw", "side"}) EXPECT_GT(spins[kind], 0) << kind;

  std::cout << "[ measured ] whole-shot suite: " << scenes.size() << " shots; balls";
  for (const auto& [n, count] : balls) std::cout << ' ' << n << ':' << count;
  std::cout << "; cushions";
  for (const auto& [c, count] : cushions) std::cout << ' ' << c << ':' << count;
  std::cout << "; real " << presets["real"] << " (stun " << spins["stun"] << ", follow "
            << spins["follow"] << ", draw " << spins["draw"] << ", side " << spins["side"]
            << "), paper " << presets["paper"] << std::endl;
}

TEST(WholeShots, DefaultSettingsMatchTheReference) {
  const WholeShotReport& r = defaultReport();
  ASSERT_GE(r.shots.size(), 40u);
  for (const WholeShotResult& s : r.shots) {
    const ShotComparison& c = s.comparison;
    EXPECT_TRUE(c.events_match) << describe(s) << ": " << c.mismatch;
    EXPECT_TRUE(c.pockets_match) << describe(s) << ": " << c.mismatch;
    EXPECT_LE(c.position_error_mm, kWholeShotPositionToleranceMm) << describe(s);
    EXPECT_LE(c.time_error_ms, kWholeShotEventTimeToleranceMs) << describe(s);
  }
  double worst_rest_ms = 0.0;
  int events = 0;
  for (const WholeShotResult& s : r.shots) {
    worst_rest_ms = std::max(worst_rest_ms, s.comparison.rest_time_error_ms);
    events += s.comparison.events_compared;
  }
  std::cout << "[ measured ] whole shots at the default settings against the reference: "
            << r.shots.size() - static_cast<std::size_t>(r.mismatched_shots) << " of "
            << r.shots.size() << " with the same events (" << events
            << " events compared); worst final position " << r.worst_position_mm << " mm (target "
            << kWholeShotPositionToleranceMm << "), worst event time " << r.worst_time_ms
            << " ms (target " << kWholeShotEventTimeToleranceMs << "), worst time of rest "
            << worst_rest_ms << " ms" << std::endl;
  std::cout << "[ measured ] whole shots, wall time summed over the shots: Box2D engine "
            << r.box2d_ms << " ms, reference engine " << r.reference_ms << " ms" << std::endl;
}

TEST(WholeShots, BreakFirstEventsMatchTheReference) {
  const BreakComparison b = compareBreak(StepParams{});
  EXPECT_TRUE(b.events_match) << b.mismatch;
  EXPECT_EQ(b.events_compared, kBreakEventsCompared) << b.mismatch;
  EXPECT_LE(b.time_error_ms, kBreakEventTimeToleranceMs);
  std::cout << "[ measured ] break, first " << kBreakEventsCompared
            << " events against the reference: " << b.events_compared << " the same"
            << (b.mismatch.empty() ? "" : " (" + b.mismatch + ")") << ", worst time "
            << b.time_error_ms << " ms (target " << kBreakEventTimeToleranceMs
            << "); to rest: Box2D engine " << b.box2d_ms << " ms, reference engine "
            << b.reference_ms << " ms" << std::endl;
}

TEST(WholeShots, ComparisonCatchesBox2DsSimultaneousSolver) {
  // Box2D's own contact solver (contacts "box2d") settles the rack's simultaneous contacts
  // all at once, not pair by pair in time order: the break's events come in another order.
  StepParams box2d_contacts;
  box2d_contacts.box2d.contacts = ContactModel::Box2D;
  const BreakComparison b = compareBreak(box2d_contacts);
  EXPECT_FALSE(b.events_match);
  EXPECT_FALSE(b.withinTolerance());
  std::cout << "[ measured ] break with Box2D's contact solver: " << b.mismatch << std::endl;
}

TEST(WholeShots, ComparisonCatchesAMovedBallAndALateEvent) {
  const Scene s = wholeShotScenes().front();
  const SimResult want = simulate(s);
  SimResult moved = want;
  const auto on_table = std::find_if(moved.balls.begin(), moved.balls.end(),
                                     [](const BallState& b) { return !b.pocket; });
  ASSERT_NE(on_table, moved.balls.end());
  on_table->pos.x += 0.002;
  const ShotComparison m = compareRuns(s, moved, want);
  EXPECT_NEAR(m.position_error_mm, 2.0, 1e-9);
  EXPECT_FALSE(m.withinTolerance());
  SimResult late = want;
  ASSERT_FALSE(late.events.empty());
  late.events.front().t += 0.002;
  const ShotComparison l = compareRuns(s, late, want);
  EXPECT_NEAR(l.time_error_ms, 2.0, 1e-9);
  EXPECT_FALSE(l.withinTolerance());
}

TEST(WholeShots, ComparisonCatchesAChangedCushion) {
  // The reference against itself with the cushion's restitution 0.84 instead of 0.85: every
  // shot that meets a cushion ends elsewhere, and the comparison must say so.
  int out_of_tolerance = 0, with_cushions = 0;
  double worst_mm = 0.0;
  for (Scene s : wholeShotScenes()) {
    s.step.engine = EngineKind::named("reference");
    const SimResult want = simulate(s);
    if (cushionEventCount(want.events) == 0) continue;
    ++with_cushions;
    Scene changed = s;
    changed.physics.cushion_restitution -= 0.01;
    const ShotComparison c = compareRuns(changed, simulate(changed), want);
    if (!c.withinTolerance()) ++out_of_tolerance;
    worst_mm = std::max(worst_mm, c.position_error_mm);
  }
  ASSERT_GT(with_cushions, 0);
  EXPECT_GT(out_of_tolerance, with_cushions / 2);
  std::cout << "[ measured ] cushion restitution 0.01 lower: " << out_of_tolerance << " of "
            << with_cushions << " shots with cushions out of tolerance, worst final position "
            << worst_mm << " mm" << std::endl;
}

TEST(WholeShots, ComparisonOfARunWithItselfIsExact) {
  const Scene s = breakScene();
  const SimResult r = simulate(s);
  const ShotComparison c = compareRuns(s, r, r);
  EXPECT_TRUE(c.events_match);
  EXPECT_TRUE(c.pockets_match);
  EXPECT_TRUE(c.mismatch.empty()) << c.mismatch;
  EXPECT_EQ(c.position_error_mm, 0.0);
  EXPECT_EQ(c.time_error_ms, 0.0);
}
