// The kept predictions: an event redoes the predictions of the balls it touched and no others,
// and what is kept is what a search from nothing would find.
#include "physics/model/event_queue.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "nineball/engine.hpp"
#include "nineball/random.hpp"
#include "nineball/scenes.hpp"
#include "physics/engines/engine_internals.hpp"

namespace nineball::physics {
namespace {

SearchWork toRest(const Scene& scene, const char* engine) {
  StepParams step = scene.step;
  step.engine = EngineKind::named(engine);
  const std::unique_ptr<Engine> w = makeEngine(scene.table, scene.physics, step);
  for (const BallState& b : scene.balls) w->addBall(b);
  w->runUntilRest();
  EXPECT_TRUE(w->atRest());
  return physics::internals(*w).searchWork();
}

double perEvent(long count, const SearchWork& w) {
  return static_cast<double>(count) / static_cast<double>(w.events);
}

// A search over every ball at each event would redo 100 balls' predictions an event here, and
// check 4,950 pairs: this fails at once if the per-event search comes back.
TEST(EventQueue, AnEventRedoesThePredictionsOfTheBallsItTouched) {
  for (const char* engine : {"box2d", "reference"}) {
    const SearchWork few = toRest(movingGridScene(9), engine);
    const SearchWork many = toRest(movingGridScene(100), engine);
    ASSERT_GT(many.events, 500);
    // An event changes one ball (a cushion, a phase, a pocket) or two (a contact); a jam a few
    // more. Each ball's own prediction is worked out once more per change, plus once at start.
    EXPECT_LE(many.ball_predictions, 2 * many.events + 100) << engine;
    EXPECT_LE(few.ball_predictions, 2 * few.events + 9) << engine;
    // Pairs are worked out for a changed ball's neighbours along its path alone: per event,
    // far fewer than the balls on the table, and growing far slower than they do.
    EXPECT_LT(perEvent(many.pair_predictions, many), 40.0) << engine;
    EXPECT_LT(perEvent(many.pair_predictions, many), 8.0 * perEvent(few.pair_predictions, few))
        << engine;
    std::printf(
        "[ measured ] %s: 9 balls %ld events, %.2f ball and %.1f pair predictions an event; "
        "100 balls %ld events, %.2f and %.1f\n",
        engine, few.events, perEvent(few.ball_predictions, few),
        perEvent(few.pair_predictions, few), many.events, perEvent(many.ball_predictions, many),
        perEvent(many.pair_predictions, many));
  }
}

// Random balls, each event "resolved" by giving its balls (and a few others) new arcs at its
// instant: the queue that keeps its predictions hands out the event a new queue, searching the
// same arcs from nothing, hands out, every time.
TEST(EventQueue, KeptPredictionsAreWhatASearchFromNothingFinds) {
  const PhysicsParams p;
  const TableGeometry table = buildTable(TableDef{}, p.ball_radius);
  const EventSearch search(table, p);
  std::uint64_t rng = 7;
  const int n = 16;
  std::vector<Arc> arcs;
  // A new arc from `at`, heading within a quarter turn of `towards`.
  auto launch = [&](double t, Vec2 at, Vec2 towards) {
    const double heading = std::atan2(towards.y, towards.x) + uniform(rng, -0.25, 0.25) * kPi;
    const Vec2 v = fromAngle(heading) * uniform(rng, 0.2, 4.0);
    const Vec3 w{uniform(rng, -80.0, 80.0), uniform(rng, -80.0, 80.0), uniform(rng, -40.0, 40.0)};
    return beginArc(t, {at, v, w}, p);
  };
  for (int i = 0; i < n; ++i) {
    const Vec2 at{-1.0 + 0.5 * (i % 4) + 0.1, -0.45 + 0.3 * (i / 4)};
    arcs.push_back(launch(0.0, at, fromAngle(uniform(rng, 0.0, 2.0 * kPi))));
  }
  std::vector<Mover> movers(n);
  auto refresh = [&] {
    for (int i = 0; i < n; ++i) movers[static_cast<std::size_t>(i)] = {&arcs[i], true};
  };
  EventQueue kept(search);
  int compared = 0;
  for (int round = 0; round < 2000; ++round) {
    refresh();
    EventQueue fresh(search);
    const NextEvent a = kept.next(movers, 1e6);
    const NextEvent b = fresh.next(movers, 1e6);
    ASSERT_EQ(static_cast<int>(a.kind), static_cast<int>(b.kind)) << "round " << round;
    if (a.kind == NextEvent::Kind::None) break;
    ASSERT_EQ(a.t, b.t) << "round " << round;
    ASSERT_EQ(a.i, b.i);
    if (a.kind == NextEvent::Kind::Ball) {
      ASSERT_EQ(a.j, b.j);
    }
    ++compared;
    // "Resolve" it: its balls start new arcs where they are, heading away from what they met
    // (the test is the queue's bookkeeping, not the physics of the contact); a pocketed ball
    // goes back to the middle of the table.
    auto restart = [&](std::size_t i, Vec2 away) {
      Vec2 at = stateAt(arcs[i], a.t, p).p;
      if (a.kind == NextEvent::Kind::Pocket) {
        at = {0.0, 0.0};
        away = fromAngle(uniform(rng, 0.0, 2.0 * kPi));
      }
      arcs[i] = launch(a.t, at, away);
      kept.changed(i);
    };
    const Vec2 at_i = stateAt(arcs[a.i], a.t, p).p;
    if (a.kind == NextEvent::Kind::Ball) {
      const Vec2 at_j = stateAt(arcs[a.j], a.t, p).p;
      restart(a.i, at_i - at_j);
      restart(a.j, at_j - at_i);
    } else if (a.kind == NextEvent::Kind::PhaseEnd) {
      arcs[a.i] = nextArc(arcs[a.i], p);
      kept.changed(a.i);
    } else {
      restart(a.i, Vec2{0.0, 0.0} - at_i);  // back towards the middle
    }
  }
  EXPECT_GT(compared, 1000);
}

}  // namespace
}  // namespace nineball::physics
