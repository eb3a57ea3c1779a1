// Micro benchmarks of the physics (Google Benchmark). The run-time-against-error sweep is
// `nineball bench`; this measures the parts.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "nineball/engine.hpp"
#include "nineball/motion.hpp"
#include "nineball/planner.hpp"
#include "nineball/random.hpp"
#include "nineball/scenes.hpp"
#include "nineball/sim.hpp"
#include "physics/engines/engine_internals.hpp"

namespace {

using namespace nineball;

void BM_BreakToRest(benchmark::State& state, StepParams step) {
  Scene scene = breakScene();
  scene.step = step;
  for (auto _ : state) benchmark::DoNotOptimize(simulate(scene));
}
StepParams onEngine(const char* name) {
  StepParams step;
  step.engine = EngineKind::named(name);
  return step;
}
BENCHMARK_CAPTURE(BM_BreakToRest, adaptive_default, StepParams{})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BreakToRest, reference_engine, onEngine("reference"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BreakToRest, plain_baseline, StepParams::plainBaseline())
    ->Unit(benchmark::kMillisecond);

// One base step with the full rack moving just after the break.
void BM_StepFullRackMoving(benchmark::State& state) {
  const Scene scene = breakScene();
  for (auto _ : state) {
    state.PauseTiming();
    const std::unique_ptr<Engine> w_engine = makeEngine(scene.table, scene.physics, scene.step);
    Engine& w = *w_engine;
    for (const BallState& b : scene.balls) w.addBall(b);
    w.strike(kCueBall, *scene.shot);
    w.runFor(0.15);  // the cue ball has reached the rack
    state.ResumeTiming();
    w.step();
  }
}
BENCHMARK(BM_StepFullRackMoving)->Unit(benchmark::kMicrosecond);

// One ball rolling 2 m among N balls at rest: resting balls sleep in Box2D and are skipped in
// the contact search, so N should cost next to nothing.
void BM_RollingAmongRestingBalls(benchmark::State& state) {
  const int resting = static_cast<int>(state.range(0));
  std::vector<BallState> balls;
  BallState cue;
  cue.id = 0;
  cue.pos = {-1.0, -0.5};
  cue.vel = {1.0, 0.0};
  cue.w = {0.0, 1.0 / 0.028575, 0.0};
  balls.push_back(cue);
  for (int i = 0; i < resting; ++i) {
    BallState b;
    b.id = i + 1;
    b.pos = {-1.1 + 0.07 * (i % 30), -0.3 + 0.07 * (i / 30)};
    balls.push_back(b);
  }
  for (auto _ : state) {
    state.PauseTiming();
    const std::unique_ptr<Engine> w_engine = makeEngine(TableDef{}, PhysicsParams{}, StepParams{});
    Engine& w = *w_engine;
    for (const BallState& b : balls) w.addBall(b);
    state.ResumeTiming();
    w.runUntilRest();
    benchmark::DoNotOptimize(w.time());
  }
}
BENCHMARK(BM_RollingAmongRestingBalls)->Arg(0)->Arg(9)->Arg(99)->Unit(benchmark::kMillisecond);

// N balls on an even grid over the table, all rolling at 3 m/s in seeded directions, to rest:
// how the contact search scales with the number of moving balls.
void BM_MovingGridToRest(benchmark::State& state, StepParams step) {
  const std::vector<BallState> balls = movingGridScene(static_cast<int>(state.range(0))).balls;
  for (auto _ : state) {
    const std::unique_ptr<Engine> w_engine = makeEngine(TableDef{}, PhysicsParams{}, step);
    Engine& w = *w_engine;
    for (const BallState& b : balls) w.addBall(b);
    w.runUntilRest();
    benchmark::DoNotOptimize(w.time());
    const physics::SearchWork work = physics::internals(w).searchWork();
    state.counters["events"] = static_cast<double>(work.events);
    state.counters["pairs"] = static_cast<double>(work.pair_predictions);
  }
}
BENCHMARK_CAPTURE(BM_MovingGridToRest, box2d, StepParams{})
    ->Arg(9)
    ->Arg(30)
    ->Arg(60)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MovingGridToRest, reference, onEngine("reference"))
    ->Arg(9)
    ->Arg(30)
    ->Arg(60)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond);

// One candidate of the planner: a cut of the 1 into a corner from a five-ball position, played
// to rest through a fresh world and scored by the rules (what `ai-bench` counts as a shot).
void BM_PlannerCandidate(benchmark::State& state) {
  ai::PlanInput in;
  in.balls = {BallState::at(0, {-0.5, 0.1}), BallState::at(1, {0.6, 0.35}),
              BallState::at(3, {0.2, -0.3}), BallState::at(5, {-0.9, -0.4}),
              BallState::at(9, {0.9, -0.1})};
  in.rack = rules::Rack(rules::RuleSet::Wpa, {1, 3, 5, 9}, false);
  const ai::ShotValuer valuer(in);
  Shot cut;
  cut.heading_rad = std::atan2(0.35 - 0.1, 0.6 + 0.5) + 0.02;  // a thin cut of the 1
  cut.speed = 2.5;
  for (auto _ : state) benchmark::DoNotOptimize(valuer.value(cut));
}
BENCHMARK(BM_PlannerCandidate)->Unit(benchmark::kMicrosecond);

void BM_TimeToTouch(benchmark::State& state) {
  // A sliding ball curving into a resting one: the quartic root of their separation.
  const PhysicsParams p;
  BallState a = BallState::at(1, {0.0, 0.0}, {2.0, 0.1});
  a.w = {-1.5, 0.8, 0.0};
  const BallState b = BallState::at(2, {0.3, 0.05});
  for (auto _ : state) benchmark::DoNotOptimize(timeToTouch(a, b, p, 1.0));
}
BENCHMARK(BM_TimeToTouch);

void BM_FreeMotion(benchmark::State& state) {
  const PhysicsParams p;
  BallState ball = BallState::at(0, {}, {2.0, 0.3});
  ball.w = {1.0, -4.0, 20.0};
  for (auto _ : state) benchmark::DoNotOptimize(freeMotion(ball, 1.0 / 60.0, p));
}
BENCHMARK(BM_FreeMotion);

}  // namespace

BENCHMARK_MAIN();
