// A ball frozen to a cushion, struck along a line of centres 45 degrees into the cushion:
// "frozen": "sequential" (the ball-ball contact, then the cushion a moment later) against
// "simultaneous" (both normal impulses from one LCP, Baraff 1989, Newton's restitution).
// Frictionless, equal masses, e the balls' restitution, s = n . c = -1/sqrt(2):
//   P_ball = m (1 + e) V / (2 - s^2), P_cushion = -s P_ball
//   object ball: (1 + e) V / (1.5 sqrt 2) along the rail (0 deg from it)
//   cue ball:    (1 - 2 (1 + e) / 3) V along the line of centres (back off for e > 0.5)
// Sequential: the object ball takes (1 + e) V / 2 into the cushion and leaves at
// atan(e_cushion) from it; the cue ball keeps (1 - e) V / 2 forward.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "nineball/params.hpp"
#include "nineball/sim.hpp"
#include "nineball/state_hash.hpp"
#include "nineball/vec2.hpp"
#include "physics/model/motion.hpp"
#include "physics/resolve/simultaneous/simultaneous.hpp"

namespace nineball::physics {
namespace {

double deg(Vec2 v) {
  return std::atan2(v.y, v.x) * 180.0 / kPi;
}

// The paper's frictionless balls and cushion, on a cloth that does not slow them.
PhysicsParams frictionless() {
  PhysicsParams p = PhysicsParams::paper();
  p.rolling_friction = 0.0;
  return p;
}

TEST(FrozenBall, LcpMatchesTheClosedForm) {
  const PhysicsParams p = frictionless();
  const double m = p.ball_mass, r = p.ball_radius, e = p.ball_restitution, V = 2.0;
  const Vec2 n{1.0 / std::sqrt(2.0), -1.0 / std::sqrt(2.0)};
  const Kinematics b{{0.0, r}, {}, {}};
  const Kinematics a{b.p - n * (2.0 * r), n * V, {}};
  const FrozenStrike hit = strikeFrozen(a, b, m, m, {0.0, 1.0}, p);
  const double p_ball = m * (1.0 + e) * V / 1.5;
  EXPECT_NEAR(hit.ball_impulse, p_ball, 1e-12);
  EXPECT_NEAR(hit.cushion_impulse, p_ball / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(hit.b.v.x, (1.0 + e) * V / (1.5 * std::sqrt(2.0)), 1e-12);
  EXPECT_NEAR(hit.b.v.y, 0.0, 1e-12);
  const Vec2 cue = n * ((1.0 - 2.0 * (1.0 + e) / 3.0) * V);
  EXPECT_NEAR(hit.a.v.x, cue.x, 1e-12);
  EXPECT_NEAR(hit.a.v.y, cue.y, 1e-12);
  EXPECT_LE(kineticEnergy(hit.a, m, r) + kineticEnergy(hit.b, m, r), kineticEnergy(a, m, r));
}

TEST(FrozenBall, TwoContactSolverPicksTheRightSet) {
  // Contact 2 parting fast on its own: only contact 1 pushes.
  TwoContacts c{{{2.0, -0.5}, {-0.5, 1.0}}, {-1.0, 5.0}, {0.5, 0.5}};
  auto impulse = solveTwoContacts(c);
  EXPECT_NEAR(impulse[0], 0.75, 1e-15);
  EXPECT_EQ(impulse[1], 0.0);
  // Nothing closing: nothing pushes.
  c.u[0] = 1.0;
  impulse = solveTwoContacts(c);
  EXPECT_EQ(impulse[0], 0.0);
  EXPECT_EQ(impulse[1], 0.0);
}

// The scene: a carom table, the object ball (2) frozen to the bottom cushion, the cue ball (1)
// 1 cm short of it, moving at V along the line of centres 45 degrees into the cushion.
struct Departure {
  Vec2 object;  // the object ball once it has left the cushion
  Vec2 cue;     // the cue ball right after the ball-ball contact
  std::uint64_t hash;
  std::size_t events;
};

Departure run(const PhysicsParams& physics, const char* engine, double speed, double gap = 0.0) {
  Scene s;
  s.table = TableDef::carom();
  s.physics = physics;
  s.step.engine = EngineKind::named(engine);
  const double r = physics.ball_radius;
  const Vec2 n{1.0 / std::sqrt(2.0), -1.0 / std::sqrt(2.0)};
  const Vec2 object{0.0, -s.table.width / 2.0 + r + gap};
  s.balls = {BallState::at(1, object - n * (2.0 * r + 0.01), n * speed), BallState::at(2, object)};
  s.until = 0.3;
  EXPECT_EQ(validateScene(s), std::nullopt);
  const SimResult result = simulate(s);
  Departure d{};
  bool hit = false, left = false;
  for (const Event& e : result.events) {
    if (!hit && e.type == EventType::BallBall) {
      hit = true;
      d.cue = e.a == 1 ? e.va : e.vb;
      d.object = e.a == 2 ? e.va : e.vb;
    } else if (hit && !left && e.type == EventType::Cushion && e.a == 2) {
      left = true;
      d.object = e.va;
    }
  }
  EXPECT_TRUE(hit && left) << engine;
  d.hash = stateHash(result.balls);
  d.events = result.events.size();
  return d;
}

PhysicsParams with(PhysicsParams p, ContactOrder frozen) {
  p.frozen = frozen;
  return p;
}

TEST(FrozenBall, BothEnginesGiveTheClosedFormAndDifferFromSequential) {
  const PhysicsParams p = frictionless();
  const double V = 2.0, e = p.ball_restitution;
  for (const char* engine : {"box2d", "reference"}) {
    const Departure before = run(with(p, ContactOrder::Sequential), engine, V);
    const Departure after = run(with(p, ContactOrder::Simultaneous), engine, V);
    std::printf(
        "[ measured ] frozen ball, paper frictionless, %s: object ball leaves the rail at %.2f "
        "deg (sequential) / %.2f deg (simultaneous); cue ball along the line of centres %.4f / "
        "%.4f of V\n",
        engine, deg(before.object), deg(after.object), dot(before.cue, normalized(Vec2{1, -1})) / V,
        dot(after.cue, normalized(Vec2{1, -1})) / V);
    // Sequential: into the cushion, then off it at atan(e_cushion).
    EXPECT_NEAR(deg(before.object), std::atan(p.cushion_restitution) * 180.0 / kPi, 1e-3);
    EXPECT_NEAR(dot(before.cue, normalized(Vec2{1, -1})), (1.0 - e) / 2.0 * V, 1e-5);
    // Simultaneous: along the rail, the cue ball sent back.
    EXPECT_NEAR(deg(after.object), 0.0, 1e-3);
    EXPECT_NEAR(length(after.object), (1.0 + e) * V / (1.5 * std::sqrt(2.0)), 1e-5);
    EXPECT_NEAR(dot(after.cue, normalized(Vec2{1, -1})), (1.0 - 2.0 * (1.0 + e) / 3.0) * V, 1e-5);
  }
}

// A ball 2 mm off the cushion (as a tracker places a frozen one): frozen only within
// frozen_tolerance; without it, it travels the 2 mm and bounces as a contact of its own.
TEST(FrozenBall, ABallWithinTheToleranceCountsAsFrozen) {
  PhysicsParams p = with(frictionless(), ContactOrder::Simultaneous);
  for (const char* engine : {"box2d", "reference"}) {
    p.frozen_tolerance = 0.0;
    const Departure apart = run(p, engine, 2.0, 0.002);
    p.frozen_tolerance = 0.003;
    const Departure frozen = run(p, engine, 2.0, 0.002);
    std::printf(
        "[ measured ] 2 mm off the cushion, %s: object ball leaves the rail at %.2f deg "
        "(frozen_tolerance 0) / %.2f deg (3 mm)\n",
        engine, deg(apart.object), deg(frozen.object));
    EXPECT_NEAR(deg(apart.object), std::atan(p.cushion_restitution) * 180.0 / kPi, 1e-3);
    EXPECT_NEAR(deg(frozen.object), 0.0, 1e-3);
  }
}

TEST(FrozenBall, RealBallsDepartCloserToTheRailAndTheCueBallComesBack) {
  for (const PhysicsParams& base : {PhysicsParams::carom(), PhysicsParams::real()}) {
    for (double V : {1.0, 3.0}) {
      for (const char* engine : {"box2d", "reference"}) {
        const Departure before = run(with(base, ContactOrder::Sequential), engine, V);
        const Departure after = run(with(base, ContactOrder::Simultaneous), engine, V);
        std::printf(
            "[ measured ] frozen ball, R %.4f, %.0f m/s, %s: object ball %.2f deg from the rail "
            "(sequential) / %.2f (simultaneous); cue ball %.4f / %.4f of V along the line of "
            "centres\n",
            base.ball_radius, V, engine, deg(before.object), deg(after.object),
            dot(before.cue, normalized(Vec2{1, -1})) / V,
            dot(after.cue, normalized(Vec2{1, -1})) / V);
        EXPECT_LT(std::abs(deg(after.object)), std::abs(deg(before.object)) - 5.0);
        EXPECT_LT(dot(after.cue, normalized(Vec2{1, -1})),
                  dot(before.cue, normalized(Vec2{1, -1})));
        // The same run again: the same bits.
        EXPECT_EQ(run(with(base, ContactOrder::Simultaneous), engine, V).hash, after.hash);
      }
    }
  }
}

TEST(FrozenBall, EnergyNeverRises) {
  std::uint64_t state = 99;
  auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  const char* cushions[] = {"simple", "mathavan", "stronge", "mathavan_speed"};
  const char* grips[] = {"frictionless", "frictional"};
  for (int k = 0; k < 4000; ++k) {
    PhysicsParams p = k % 2 ? PhysicsParams::carom() : PhysicsParams::real();
    p.cushion = CushionModel::named(cushions[k % 4]);
    p.ball_ball = BallBallModel::named(grips[(k / 4) % 2]);
    p.ball_restitution = next();
    p.cushion_restitution = next();
    const double r = p.ball_radius, ma = 0.1 + next() * 0.3, mb = 0.1 + next() * 0.3;
    const double a = -kPi * (0.05 + 0.9 * next());  // the line of centres, into the cushion
    const Vec2 n{std::cos(a), std::sin(a)};
    const double speed = 0.01 + 8.0 * next(), w = 2.5 * speed / r;
    const Vec2 v = fromAngle(a + (next() - 0.5) * 0.9 * kPi) * speed;
    const Kinematics kb{{0.0, r}, {(next() - 0.5) * 0.1, 0.0}, {(2 * next() - 1) * w, 0.0, 0.0}};
    const Kinematics ka{kb.p - n * (2.0 * r),
                        v,
                        {(2 * next() - 1) * w, (2 * next() - 1) * w, (2 * next() - 1) * w}};
    const FrozenStrike hit = strikeFrozen(ka, kb, ma, mb, {0.0, 1.0}, p);
    const double in = kineticEnergy(ka, ma, r) + kineticEnergy(kb, mb, r);
    ASSERT_LE(kineticEnergy(hit.a, ma, r) + kineticEnergy(hit.b, mb, r), in * (1.0 + 1e-12)) << k;
    ASSERT_GE(hit.b.v.y, -1e-9) << k;  // not into the cushion
  }
}

}  // namespace
}  // namespace nineball::physics
