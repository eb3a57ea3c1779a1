// A ball into a corner: "corner": "sequential" (one cushion, then the other) against
// "simultaneous" (both normal impulses from one LCP when the second cushion is met within
// cushion_contact_time). Frictionless closed form, a wedge whose faces' normals are 60 deg
// apart, the ball straight in along its bisector at V with cushion restitution e: both faces
// push P = m (1 + e) V cos 30 / 1.5 and the ball comes straight back at e V. Square corners
// decouple the two normals, so there the frictionless answer is the same either way; with the
// real cushions the first cushion's friction turns the ball before the second acts when taken
// one after the other, while together a ball in at 45 deg leaves along the line it came in on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "nineball/params.hpp"
#include "nineball/sim.hpp"
#include "nineball/state_hash.hpp"
#include "nineball/vec2.hpp"
#include "physics/model/motion.hpp"
#include "physics/resolve/simultaneous/simultaneous.hpp"

namespace nineball::physics {
namespace {

TEST(Corner, WedgeMatchesTheClosedForm) {
  PhysicsParams p = PhysicsParams::paper();
  const double m = p.ball_mass, e = p.cushion_restitution, V = 2.0;
  const Vec2 first{0.0, 1.0}, second{std::sin(kPi / 3.0), std::cos(kPi / 3.0)};
  const Vec2 bisector = normalized(first + second);
  const Kinematics in{{}, bisector * -V, {}};
  const CornerBounce out = intoCorner(in, first, second, m, p);
  const double expected = m * (1.0 + e) * V * std::cos(kPi / 6.0) / 1.5;
  EXPECT_NEAR(out.impulse[0], expected, 1e-12);
  EXPECT_NEAR(out.impulse[1], expected, 1e-12);
  EXPECT_NEAR(out.k.v.x, bisector.x * e * V, 1e-12);
  EXPECT_NEAR(out.k.v.y, bisector.y * e * V, 1e-12);
  // One after the other: off the first face, then the second: not back along the bisector.
  Vec2 v = in.v;
  v -= first * ((1.0 + e) * dot(v, first));
  if (dot(v, second) < 0.0) v -= second * ((1.0 + e) * dot(v, second));
  std::printf(
      "[ measured ] wedge of 60 deg between normals, frictionless, e %.2f: sequential leaves "
      "%.2f deg off the bisector at %.4f V, simultaneous %.2f deg at %.4f V (closed form 0, e)\n",
      e, std::acos(std::min(1.0, dot(normalized(v), bisector))) * 180.0 / kPi, length(v) / V,
      std::acos(std::min(1.0, dot(normalized(out.k.v), bisector))) * 180.0 / kPi,
      length(out.k.v) / V);
  EXPECT_GT(std::acos(std::min(1.0, dot(normalized(v), bisector))), 0.1);
}

TEST(Corner, OnlyAFaceMetWithinTheContactTimeJoins) {
  const Cushions cushions = Cushions::of(buildTable(TableDef::carom(), 0.03075));
  const double r = 0.03075, hx = 1.42, hy = 0.71;
  // On the bottom cushion, 3 mm from the left one, moving at 45 deg into both at 2 m/s: the
  // left cushion is 3 mm / 1.414 m/s = 2.1 ms away.
  const Kinematics k{{-hx + r + 0.003, -hy + r}, {-std::sqrt(2.0), -std::sqrt(2.0)}, {}};
  EXPECT_TRUE(secondFace(k, {0.0, 1.0}, r, cushions, 0.01).has_value());
  EXPECT_FALSE(secondFace(k, {0.0, 1.0}, r, cushions, 0.002).has_value());
  // Moving away from the left cushion: no corner.
  const Kinematics away{k.p, {std::sqrt(2.0), -std::sqrt(2.0)}, {}};
  EXPECT_FALSE(secondFace(away, {0.0, 1.0}, r, cushions, 0.01).has_value());
}

struct Exit {
  Vec2 v;  // after the corner (the last cushion event within 20 ms of the first)
  int cushions = 0;
  std::uint64_t hash = 0;
};

// A rolling ball into the bottom-left corner of a carom table at 45 deg, meeting the bottom
// cushion `offset` metres from the left one.
Exit run(PhysicsParams physics, const char* engine, double speed, double offset, ContactOrder o) {
  physics.corner = o;
  Scene s;
  s.table = TableDef::carom();
  s.physics = physics;
  s.step.engine = EngineKind::named(engine);
  const double r = physics.ball_radius;
  const Vec2 corner{-s.table.length / 2.0 + r + offset, -s.table.width / 2.0 + r};
  const Vec2 v = Vec2{-1.0, -1.0} * (speed / std::sqrt(2.0));
  BallState b = BallState::at(1, corner + Vec2{0.05, 0.05}, v);
  b.w = {-v.y / r, v.x / r, 0.0};
  s.balls = {b};
  s.until = 0.15;
  EXPECT_EQ(validateScene(s), std::nullopt);
  const SimResult result = simulate(s);
  Exit out;
  double first = -1.0;
  for (const Event& e : result.events) {
    if (e.type != EventType::Cushion) continue;
    if (first < 0.0) first = e.t;
    if (e.t - first > 0.02) break;
    out.v = e.va;
    ++out.cushions;
  }
  out.hash = stateHash(result.balls);
  return out;
}

double fromDiagonal(Vec2 v) {
  return std::atan2(v.y, v.x) * 180.0 / kPi - 45.0;
}

TEST(Corner, SquareCornerAt45DegreesLeavesAlongItsPath) {
  for (double speed : {0.5, 1.0, 2.0, 3.0, 5.0}) {
    for (const char* engine : {"box2d", "reference"}) {
      const PhysicsParams p = PhysicsParams::carom();
      const Exit before = run(p, engine, speed, 0.0, ContactOrder::Sequential);
      const Exit after = run(p, engine, speed, 0.0, ContactOrder::Simultaneous);
      std::printf(
          "[ measured ] carom corner at 45 deg, rolling, %.1f m/s, %s: leaves %+.2f deg off the "
          "diagonal at %.4f of the speed (sequential, %d cushion events) / %+.2f deg at %.4f "
          "(simultaneous, %d)\n",
          speed, engine, fromDiagonal(before.v), length(before.v) / speed, before.cushions,
          fromDiagonal(after.v), length(after.v) / speed, after.cushions);
      EXPECT_EQ(after.cushions, 2);
      EXPECT_NEAR(fromDiagonal(after.v), 0.0, 1e-6);
      EXPECT_GT(std::abs(fromDiagonal(before.v)), 1.0);
      EXPECT_EQ(run(p, engine, speed, 0.0, ContactOrder::Simultaneous).hash, after.hash);
    }
  }
}

TEST(Corner, NearTheCornerWithinTheContactTime) {
  for (double offset : {0.001, 0.005}) {
    for (const char* engine : {"box2d", "reference"}) {
      const PhysicsParams p = PhysicsParams::carom();
      const Exit before = run(p, engine, 2.0, offset, ContactOrder::Sequential);
      const Exit after = run(p, engine, 2.0, offset, ContactOrder::Simultaneous);
      std::printf(
          "[ measured ] carom corner at 45 deg, 2 m/s, %.0f mm from the corner, %s: %+.2f deg "
          "off the diagonal (sequential) / %+.2f (simultaneous)\n",
          offset * 1000.0, engine, fromDiagonal(before.v), fromDiagonal(after.v));
      EXPECT_EQ(after.cushions, 2);
      EXPECT_LT(std::abs(fromDiagonal(after.v)), std::abs(fromDiagonal(before.v)));
    }
  }
}

TEST(Corner, EnergyNeverRises) {
  std::uint64_t state = 7;
  auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  const char* cushions[] = {"simple", "mathavan", "stronge", "mathavan_speed"};
  for (int k = 0; k < 4000; ++k) {
    PhysicsParams p = k % 2 ? PhysicsParams::carom() : PhysicsParams::real();
    p.cushion = CushionModel::named(cushions[k % 4]);
    p.cushion_restitution = next();
    p.cushion_friction = next();
    const double r = p.ball_radius, m = p.ball_mass;
    const double between = kPi * (0.05 + 0.9 * next());  // the angle between the normals
    const Vec2 first{0.0, 1.0}, second = fromAngle(kPi / 2.0 - between);
    const double speed = 0.01 + 8.0 * next(), w = 2.5 * speed / r;
    // Into both faces.
    const Vec2 in = normalized(first + second) * -1.0;
    const Vec2 v = fromAngle(std::atan2(in.y, in.x) + (next() - 0.5) * (kPi - between)) * speed;
    const Kinematics ball{
        {}, v, {(2 * next() - 1) * w, (2 * next() - 1) * w, (2 * next() - 1) * w}};
    const CornerBounce out = intoCorner(ball, first, second, m, p);
    ASSERT_LE(kineticEnergy(out.k, m, r), kineticEnergy(ball, m, r) * (1.0 + 1e-12)) << k;
    ASSERT_GE(dot(out.k.v, first), -1e-9) << k;
    ASSERT_GE(dot(out.k.v, second), -1e-9) << k;
  }
}

}  // namespace
}  // namespace nineball::physics
