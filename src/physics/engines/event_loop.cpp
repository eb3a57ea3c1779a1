#include "physics/engines/event_loop.hpp"

#include <algorithm>

#include "common/limits.hpp"
#include "common/log.hpp"
#include "nineball/cancel.hpp"

namespace nineball::physics {
namespace {

// More events than this in a sixtieth of a second (a frozen cluster caught in a loop) end the
// run: its result is partial, and says so. Runs longer than that may hold as many more as their
// length calls for.
constexpr std::size_t kEventsPerPeriodBase = 10000;
constexpr std::size_t kEventsPerPeriodPerBall = 100;
constexpr double kCapPeriod = 1.0 / 60.0;

bool runOver(const LoopEngine& engine, const RunState& run, double deadline) {
  return engine.settled() || run.time >= deadline || run.exhausted;
}

void spend(RunState& run, std::size_t count, std::size_t cap) {
  run.exhausted = true;
  run.budget_spent = run.resolved >= limits::kMaxEvents
                         ? std::to_string(limits::kMaxEvents) + " contacts"
                     : run.pieces >= limits::kMaxPieces
                         ? std::to_string(limits::kMaxPieces) + " pieces"
                         : std::to_string(cap) +
                               " contacts in one step (a run of contacts that makes no progress)";
  physicsLogger().info(
      "t={:.6f}: work budget spent ({} events, {} in this run; {} pieces); stopped", run.time,
      run.resolved, count, run.pieces);
}

}  // namespace

void runEvents(LoopEngine& engine, EventQueue& queue, RunState& run, double end, bool to_rest,
               std::vector<Event>& events) {
  engine.beginRun();
  const double periods = std::max(1.0, (end - run.time) / kCapPeriod);
  const auto cap = static_cast<std::size_t>(
      periods *
      static_cast<double>(kEventsPerPeriodBase + kEventsPerPeriodPerBall * engine.ballCount()));
  std::size_t count = 0;
  bool was_settled = engine.settled();
  while (run.time < end && !(to_rest && was_settled) && !run.exhausted) {
    const double limit = engine.describe(run.movers, end);
    const NextEvent e = queue.next(run.movers, limit);
    if (e.t > run.time) {
      engine.carry(e.t - run.time);
      ++run.pieces;
    }
    run.time = e.t;
    engine.resolve(e);
    // A piece with no event counts all the same: it is no progress in a loop that makes none.
    ++count;
    if (e.kind != NextEvent::Kind::None) ++run.resolved;
    if (cancelRequested()) {
      run.exhausted = true;
      run.budget_spent = kCancelledBudget;
    } else if (count >= cap || run.resolved >= limits::kMaxEvents ||
               run.pieces >= limits::kMaxPieces) {
      spend(run, count, cap);
    }
    const bool now_settled = engine.settled();
    if (!was_settled && now_settled) {
      Event rest;
      rest.type = EventType::AllAtRest;
      rest.t = run.time;
      events.push_back(rest);
    }
    was_settled = now_settled;
  }
}

bool stepTowardRest(LoopEngine& engine, EventQueue& queue, RunState& run, double hz,
                    double deadline, std::vector<Event>& events) {
  if (!runOver(engine, run, deadline)) {
    runEvents(engine, queue, run, std::min(stepBoundary(++run.steps, hz), deadline), true, events);
  }
  return runOver(engine, run, deadline);
}

void noteStillMoving(const LoopEngine& engine, const RunState& run, double max_time) {
  if (!engine.settled() && !run.exhausted) {
    physicsLogger().info("balls still moving after {} s of simulated time; stopped", max_time);
  }
}

}  // namespace nineball::physics
