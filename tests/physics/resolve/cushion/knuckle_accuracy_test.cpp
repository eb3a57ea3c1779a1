// Accuracy of the rebound at a knuckle (a snooker table's rounded jaw). A ball rolled into
// every knuckle at many headings is met on the arc (R + rho from its centre), leaves as the
// cushion model says for the arc's normal at the contact, and comes to rest on the cloth,
// never inside the cushions. Tolerances: 1e-9 m and 1e-9 m/s, the rounding of the closed-form
// clocks over a 0.3 m run; a sink of kSinkTolerance, half the engines' touch tolerance, below
// which they count a contact as met on time.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "nineball/engine.hpp"
#include "nineball/params.hpp"
#include "nineball/table.hpp"
#include "physics/model/motion.hpp"
#include "physics/resolve/ball_ball/collide.hpp"
#include "physics/resolve/cushion/registry.hpp"

namespace nineball::physics {
namespace {

constexpr double kSinkTolerance = 0.5 * kTouchTolerance;

struct Tally {
  int on_arc = 0;     // shots whose first contact was the knuckle
  int elsewhere = 0;  // steep headings that met the nose or the jaw face first
};

// The ball rolls (no slip) at 2 m/s from 0.3 m out, aimed to meet the knuckle at the point
// whose normal is n, along a heading rotated `heading` from -n.
Tally rollIntoEveryKnuckle(const PhysicsParams& p, const std::string& engine_name) {
  const TableDef def = TableDef::snooker();
  const TableGeometry table = buildTable(def, p.ball_radius);
  const double r = p.ball_radius;
  const double mass = p.ball_mass;
  Tally tally;
  for (const CushionArc& arc : table.arcs) {
    const Vec2 from = normalized(arc.start - arc.centre), to = normalized(arc.end - arc.centre);
    for (double f = 0.1; f < 0.95; f += 0.2) {
      const Vec2 n = normalized(from * (1.0 - f) + to * f);
      const Vec2 touch = arc.centre + n * (r + arc.radius);
      for (double deg = -80.0; deg <= 80.0; deg += 10.0) {
        const Vec2 back = rotated(n, degToRad(deg));
        Kinematics k0{touch + back * 0.3, back * -2.0, {}};
        k0.w = {-k0.v.y / r, k0.v.x / r, 0.0};  // rolling: the slip R (-w.y, w.x) + v is 0
        if (!table.ballFits(k0.p, r)) continue;
        StepParams step;
        step.engine = EngineKind::named(engine_name);
        auto engine = makeEngine(def, p, step);
        BallState ball = BallState::at(kCueBall, k0.p, k0.v);
        ball.w = k0.w;
        engine->addBall(ball);
        engine->runUntilRest();
        const std::vector<Event>& events = engine->events();
        if (events.empty()) {
          ADD_FAILURE() << engine_name << ": no event, heading " << deg;
          continue;
        }
        const BallState rest = engine->balls().front();
        if (!rest.pocket) {
          EXPECT_LE(cushionSink(table, rest.pos, r), kSinkTolerance)
              << engine_name << " at " << rest.pos.x << ", " << rest.pos.y;
          EXPECT_TRUE(table.insideLoop(rest.pos));
        }
        const Event& first = events.front();
        if (first.type != EventType::Cushion) {
          ADD_FAILURE() << engine_name << ": the first event is no cushion, heading " << deg;
          continue;
        }
        const Kinematics before = stateAt(beginArc(0.0, k0, p), first.t, p);
        const Vec2 d = before.p - arc.centre;
        if (std::abs(length(d) - (r + arc.radius)) > 1e-9 || !arc.covers(d)) {
          ++tally.elsewhere;
          continue;
        }
        ++tally.on_arc;
        const Vec2 normal = normalized(d);
        double impulse = 0.0;
        const CushionModelDef& model = cushionModel(p.cushion);
        const Vec2 expected =
            model.bounce
                ? model.bounce(before, normal, mass, p, impulse).v
                : before.v - normal * ((1.0 + p.cushion_restitution) * dot(before.v, normal));
        EXPECT_NEAR(first.va.x, expected.x, 1e-9) << engine_name << ", heading " << deg;
        EXPECT_NEAR(first.va.y, expected.y, 1e-9) << engine_name << ", heading " << deg;
        // What the model keeps: the simple law keeps the speed along the arc's tangent; every
        // model gives back no energy.
        if (!model.bounce) {
          const Vec2 tangent{-normal.y, normal.x};
          EXPECT_NEAR(dot(first.va, tangent), dot(before.v, tangent), 1e-9);
        }
        EXPECT_LE(dot(first.va, first.va), dot(before.v, before.v) * (1.0 + 1e-12));
      }
    }
  }
  return tally;
}

TEST(KnuckleAccuracy, TheSnookerPresetReboundsAsMathavansModelSaysForTheArcNormal) {
  const Tally t = rollIntoEveryKnuckle(PhysicsParams::snooker(), "reference");
  EXPECT_GT(t.on_arc, 300) << t.elsewhere << " met the nose or jaw face first";
}

TEST(KnuckleAccuracy, TheRestitutionLawKeepsTheTangentSpeedOnTheArc) {
  PhysicsParams p = PhysicsParams::snooker();
  p.cushion = CushionModel::named("simple");
  p.cushion_friction = 0.0;  // the law alone, no rail friction after it
  p.cloth = ClothModel::Friction;
  const Tally t = rollIntoEveryKnuckle(p, "reference");
  EXPECT_GT(t.on_arc, 300) << t.elsewhere << " met the nose or jaw face first";
}

TEST(KnuckleAccuracy, TheBox2DEngineAlsoLeavesEveryBallOnTheCloth) {
  const Tally t = rollIntoEveryKnuckle(PhysicsParams::snooker(), "box2d");
  EXPECT_GT(t.on_arc, 300) << t.elsewhere << " met the nose or jaw face first";
}

}  // namespace
}  // namespace nineball::physics
