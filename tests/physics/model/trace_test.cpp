// Traces: samples read off the closed form each ball follows, checked against the paper's
// formulas, against the arcs themselves, between the two engines, and for their instants.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "common/limits.hpp"
#include "nineball/scenes.hpp"
#include "nineball/sim.hpp"
#include "physics/model/motion.hpp"

using namespace nineball;

namespace {

// Positions from the reference engine are exact to rounding; the Box2D engine starts each arc
// from Box2D's single-precision position (about 1e-7 m at the table's edge at scale 50).
constexpr double kReferenceTolerance = 1e-9;
constexpr double kBox2DTolerance = 1e-6;
// The two engines' traces of a shot that is not chaotic, sample by sample.
constexpr double kEnginesAgree = 1e-5;

const EngineKind kEngines[] = {EngineKind::named("box2d"), EngineKind::named("reference")};

double tolerance(EngineKind e) {
  return e == EngineKind::named("reference") ? kReferenceTolerance : kBox2DTolerance;
}

Scene stunShot(EngineKind engine, double v0) {
  Scene s;
  s.step.engine = engine;
  s.balls = {BallState::at(0, {-0.9, 0.0})};
  s.shot = Shot::withSpeed(0.0, v0);
  s.until = 1.0;
  s.trace = TraceRequest{200.0, false};
  return s;
}

// A follow shot into one ball, which then runs into cushions: not chaotic, so that the
// engines must agree along the whole path.
Scene followShot(EngineKind engine, TraceRequest trace) {
  Scene s;
  s.step.engine = engine;
  s.balls = {BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.0, 0.03})};
  Shot shot = Shot::withSpeed(0.0, 3.0);
  shot.tip = {0.0, 0.3};
  s.shot = shot;
  s.trace = trace;
  return s;
}

Scene breakShot(EngineKind engine, TraceRequest trace) {
  Scene s = breakScene(1, 10.0);
  s.step.engine = engine;
  s.trace = trace;
  return s;
}

std::set<double> eventInstants(const SimResult& r) {
  std::set<double> ts;
  for (const Event& e : r.events) ts.insert(e.t);
  return ts;
}

}  // namespace

TEST(Trace, StunShotSlidesThenRollsAsThePapersClosedFormSays) {
  // paper-formulas.md 6 and 8: a centre hit slides with v = v0 - mu_s g t until
  // t1 = 2 v0 / (7 mu_s g), then rolls at 5/7 v0 losing mu_r g per second.
  const PhysicsParams p;
  const double g = p.gravity, mus = p.sliding_friction, mur = p.rolling_friction;
  for (EngineKind engine : kEngines) {
    for (double v0 : {1.0, 2.5}) {
      const Scene scene = stunShot(engine, v0);
      const SimResult r = simulate(scene);
      ASSERT_TRUE(r.trace);
      ASSERT_EQ(r.trace->balls.size(), 1u);
      const BallTrace& b = r.trace->balls[0];
      const double t1 = 2.0 * v0 / (7.0 * mus * g);
      const double x1 = -0.9 + v0 * t1 - 0.5 * mus * g * t1 * t1;
      // The grid (201 instants over 1 s at 200 Hz) and the instant the slide ends.
      ASSERT_EQ(b.size(), 202u) << engine.name();
      EXPECT_TRUE(std::any_of(b.t.begin(), b.t.end(), [&](double t) {
        return std::abs(t - t1) < 1e-12;
      })) << "the slide's end is sampled";
      double worst_speed = 0.0, worst_x = 0.0;
      for (std::size_t i = 0; i < b.size(); ++i) {
        const double t = b.t[i];
        const bool sliding = t < t1 - 1e-12;
        const double v = sliding ? v0 - mus * g * t : 5.0 / 7.0 * v0 - mur * g * (t - t1);
        const double x = sliding
                             ? -0.9 + v0 * t - 0.5 * mus * g * t * t
                             : x1 + 5.0 / 7.0 * v0 * (t - t1) - 0.5 * mur * g * (t - t1) * (t - t1);
        worst_speed = std::max(worst_speed, std::abs(std::hypot(b.vx[i], b.vy[i]) - v));
        worst_x = std::max(worst_x, std::abs(b.x[i] - x));
        EXPECT_EQ(b.phase[i], sliding ? TracePhase::Sliding : TracePhase::Rolling) << t;
        EXPECT_NEAR(b.y[i], 0.0, 1e-12);
        // Sliding friction spins the ball up about y: w_y = 5 mu_s g t / (2 R); rolling, v / R.
        const double wy = sliding ? 2.5 * mus * g * t / p.ball_radius : v / p.ball_radius;
        EXPECT_NEAR(b.w[i].y, wy, 1e-9 * wy + 1e-9) << t;
      }
      EXPECT_LT(worst_speed, 1e-9) << engine.name();
      EXPECT_LT(worst_x, tolerance(engine)) << engine.name();
      std::cout << "[ measured ] stun shot trace, " << engine.name() << ", v0 " << v0
                << ": worst speed error " << worst_speed << " m/s, worst position error " << worst_x
                << " m\n";
    }
  }
}

TEST(Trace, EverySampleLiesOnTheArcFromTheSampleBefore) {
  // From each sample's state the closed form (beginArc, stateAt evaluated here) must reach the
  // next sample's position: every phase change and event instant is itself a sample, so no
  // pair of samples straddles one (positions are continuous across contacts).
  for (EngineKind engine : kEngines) {
    const SimResult r = simulate(breakShot(engine, {100.0, false}));
    ASSERT_TRUE(r.trace);
    const PhysicsParams p;
    double worst = 0.0;
    std::size_t pairs = 0;
    for (const BallTrace& b : r.trace->balls) {
      for (std::size_t i = 0; i + 1 < b.size(); ++i) {
        if (b.phase[i] == TracePhase::Pocketed || b.phase[i + 1] == TracePhase::Pocketed) continue;
        const physics::Kinematics k{{b.x[i], b.y[i]}, {b.vx[i], b.vy[i]}, b.w[i]};
        const physics::Arc arc = physics::beginArc(b.t[i], k, p);
        const Vec2 next = physics::stateAt(arc, b.t[i + 1], p).p;
        worst = std::max(worst, length(next - Vec2{b.x[i + 1], b.y[i + 1]}));
        ++pairs;
      }
    }
    EXPECT_GT(pairs, 1000u);
    EXPECT_LT(worst, tolerance(engine)) << engine.name();
    std::cout << "[ measured ] break trace, " << engine.name() << ": " << pairs
              << " sample pairs, worst distance off the arc " << worst << " m\n";
  }
}

TEST(Trace, BothEnginesTraceTheSamePath) {
  const SimResult box2d = simulate(followShot(EngineKind::named("box2d"), {200.0, false}));
  const SimResult exact = simulate(followShot(EngineKind::named("reference"), {200.0, false}));
  ASSERT_TRUE(box2d.trace && exact.trace);
  ASSERT_EQ(box2d.trace->balls.size(), 2u);
  double worst = 0.0;
  std::size_t compared = 0;
  for (std::size_t n = 0; n < 2; ++n) {
    const BallTrace& a = box2d.trace->balls[n];
    const BallTrace& b = exact.trace->balls[n];
    // The grid instants are the same in both; event instants differ by rounding.
    std::size_t j = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      while (j < b.size() && b.t[j] < a.t[i]) ++j;
      if (j == b.size() || b.t[j] != a.t[i]) continue;
      worst = std::max(worst, std::hypot(a.x[i] - b.x[j], a.y[i] - b.y[j]));
      EXPECT_EQ(a.phase[i], b.phase[j]) << "ball " << a.id << " t " << a.t[i];
      ++compared;
    }
  }
  EXPECT_GT(compared, 400u);
  EXPECT_LT(worst, kEnginesAgree);
  std::cout << "[ measured ] follow shot traced by both engines: " << compared
            << " samples, worst distance " << worst << " m\n";
}

TEST(Trace, EventsOnlyGivesOneSamplePerEventPerBall) {
  for (EngineKind engine : kEngines) {
    const SimResult r = simulate(breakShot(engine, {0.0, true}));
    ASSERT_TRUE(r.trace);
    const std::set<double> instants = eventInstants(r);
    ASSERT_GT(instants.size(), 20u);
    ASSERT_EQ(r.trace->balls.size(), r.balls.size());
    for (std::size_t n = 0; n < r.balls.size(); ++n) {
      const BallTrace& b = r.trace->balls[n];
      EXPECT_EQ(b.id, r.balls[n].id);
      EXPECT_EQ(std::vector<double>(instants.begin(), instants.end()), b.t);
      EXPECT_EQ(b.x.size(), b.t.size());
      EXPECT_EQ(b.phase.size(), b.t.size());
    }
    // A ball is "pocketed" from its pocket event on, where its centre entered the drop circle.
    for (const Event& e : r.events) {
      if (e.type != EventType::Pocket) continue;
      for (const BallTrace& b : r.trace->balls) {
        if (b.id != e.a) continue;
        const auto at = std::find(b.t.begin(), b.t.end(), e.t) - b.t.begin();
        EXPECT_EQ(b.phase[at], TracePhase::Pocketed);
        EXPECT_EQ(b.phase.back(), TracePhase::Pocketed);
        if (at > 0) {
          EXPECT_NE(b.phase[at - 1], TracePhase::Pocketed);
        }
      }
    }
    EXPECT_FALSE(r.trace->truncated);
  }
}

TEST(Trace, HzTraceHoldsTheGridTheEventsAndTheEnd) {
  for (EngineKind engine : kEngines) {
    const SimResult r = simulate(followShot(engine, {50.0, false}));
    ASSERT_TRUE(r.trace);
    const std::vector<double>& t = r.trace->balls[0].t;
    EXPECT_TRUE(std::is_sorted(t.begin(), t.end()));
    EXPECT_EQ(std::adjacent_find(t.begin(), t.end()), t.end()) << "instants are distinct";
    EXPECT_EQ(t.front(), 0.0);
    EXPECT_EQ(t.back(), r.time);
    for (double e : eventInstants(r)) {
      EXPECT_TRUE(std::binary_search(t.begin(), t.end(), e)) << e;
    }
    for (int k = 0; k / 50.0 <= r.time; ++k) {
      EXPECT_TRUE(std::binary_search(t.begin(), t.end(), k / 50.0)) << k;
    }
    // The run ends at rest: the last sample of each ball is at rest.
    for (const BallTrace& b : r.trace->balls) {
      EXPECT_TRUE(b.phase.back() == TracePhase::Rest || b.phase.back() == TracePhase::Spinning ||
                  b.phase.back() == TracePhase::Pocketed);
    }
  }
}

TEST(Trace, ALongRunKeepsItsEarliestSamplesWithinTheBound) {
  // Two balls at 10 kHz for 60 s would need 1,200,000 samples: the earliest 1,000,000 stay.
  Scene s = followShot(EngineKind::named("reference"), {limits::kMaxTraceHz, false});
  s.physics.rolling_friction = 0.001;
  s.until = 60.0;
  const SimResult r = simulate(s);
  ASSERT_TRUE(r.trace);
  EXPECT_TRUE(r.trace->truncated);
  std::size_t total = 0;
  for (const BallTrace& b : r.trace->balls) total += b.size();
  EXPECT_LE(total, limits::kMaxTraceSamples);
  EXPECT_GT(total, limits::kMaxTraceSamples - 2);
  EXPECT_EQ(r.trace->balls[0].t.front(), 0.0);
}

TEST(Trace, NoTraceUnlessAsked) {
  Scene s = stunShot(EngineKind::named("box2d"), 1.0);
  s.trace.reset();
  EXPECT_FALSE(simulate(s).trace);
}
