#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "physics/physics_fixtures.hpp"

namespace nineball::physics_test {
namespace {

// Where a ball meets a rail: a point on the cushion nose and the rail's inward normal.
struct Rail {
  const char* name;
  Vec2 nose;
  Vec2 inward;
};

// Points halfway between a side and a corner pocket (or mid short rail): no jaw near.
Rail topRail(const TableDef& t) {
  return {"top", {0.6, t.width / 2.0}, {0.0, -1.0}};
}
Rail bottomRail(const TableDef& t) {
  return {"bottom", {-0.6, -t.width / 2.0}, {0.0, 1.0}};
}
Rail footRail(const TableDef& t) {
  return {"foot", {t.length / 2.0, 0.2}, {-1.0, 0.0}};
}

struct Bounce {
  Event hit;
  Vec2 u;  // velocity just before the cushion
};

// A ball that meets `rail` at `angle_deg` from its normal (a positive angle turns the incoming
// direction anticlockwise), read at its first cushion event.
Bounce bounce(const PhysicsParams& p, const Rail& rail, double angle_deg, double speed,
              const StepParams& sp = StepParams{}, double approach = 0.25) {
  const TableDef table;
  const Vec2 dir = rotated(-rail.inward, degToRad(angle_deg));
  const Vec2 contact = rail.nose + rail.inward * p.ball_radius;
  const Vec2 start = contact - dir * approach;
  auto world = makeWorld(table, p, sp, {makeBall(kCueBall, start, dir * speed)});
  const auto hit = runUntilEvent(*world, EventType::Cushion, 5.0);
  EXPECT_TRUE(hit.has_value()) << rail.name << " angle " << angle_deg << " speed " << speed;
  if (!hit) return {};
  // The cloth's constant deceleration over the approach (none when frictionless).
  const double u = std::sqrt(speed * speed - 2.0 * p.rolling_friction * p.gravity * approach);
  return {*hit, dir * u};
}

// The paper's rail (section 7): the normal part reversed and scaled by e_c, the tangential
// part kept.
Vec2 formula(Vec2 u, Vec2 inward, double e_c) {
  const double un = dot(u, inward);
  return u - inward * un - inward * (e_c * un);
}

TEST(Cushion, NormalPartScaledTangentialPartKept) {
  WorstError normal("cushion: normal speed after (e_c times)", kCushionTolerance);
  WorstError tangential("cushion: tangential speed after (kept)", kCushionTolerance);
  const TableDef table;
  for (const PhysicsParams& preset : {PhysicsParams::real(), PhysicsParams::paper()}) {
    const PhysicsParams p = frictionless(preset);
    for (const Rail& rail : {topRail(table), bottomRail(table), footRail(table)}) {
      for (double angle : {0.0, 30.0, 60.0, -30.0}) {
        for (double speed : {1.0, 3.0, 8.0}) {
          const std::string where = std::string(rail.name) + " e_c " +
                                    std::to_string(p.cushion_restitution) + " angle " +
                                    std::to_string(angle) + " speed " + std::to_string(speed);
          const Bounce b = bounce(p, rail, angle, speed);
          const Vec2 want = formula(b.u, rail.inward, p.cushion_restitution);
          const Vec2 t = perp(rail.inward);
          normal.check(relativeError(dot(b.hit.va, rail.inward), dot(want, rail.inward), speed),
                       where);
          tangential.check(relativeError(dot(b.hit.va, t), dot(want, t), speed), where);
        }
      }
    }
  }
}

TEST(Cushion, SlowBallStillBounces) {
  // Box2D's default restitution threshold (1 unit/s) would make these contacts dead. The
  // balls start 1 mm from the rail so that the cloth cannot stop them first.
  WorstError normal("cushion: slow ball normal speed after", kCushionTolerance);
  const TableDef table;
  for (const PhysicsParams& preset : {PhysicsParams::real(), PhysicsParams::paper()}) {
    for (double speed : {0.2, 0.05}) {
      const Bounce b =
          bounce(constantDeceleration(preset), topRail(table), 0.0, speed, StepParams{}, 0.001);
      const double want = preset.cushion_restitution * length(b.u);
      normal.check(
          relativeError(dot(b.hit.va, topRail(table).inward), want, speed),
          "e_c " + std::to_string(preset.cushion_restitution) + " speed " + std::to_string(speed));
      EXPECT_LE(std::abs(b.hit.va.x), kCushionTolerance * want);
    }
  }
}

TEST(Cushion, BounceIsTheSameAtAnyStepRate) {
  // 60 Hz makes the world sub-step an 8 m/s ball; the rebound must not change.
  WorstError velocity("cushion: velocity after at 60/120/2000 Hz", kCushionTolerance);
  const TableDef table;
  const PhysicsParams p = frictionless();
  for (double hz : {60.0, 120.0, 2000.0}) {
    StepParams sp;
    sp.hz = hz;
    for (double speed : {0.2, 3.0, 8.0}) {
      const Bounce b = bounce(p, topRail(table), 30.0, speed, sp);
      const Vec2 want = formula(b.u, topRail(table).inward, p.cushion_restitution);
      velocity.check(vectorError(b.hit.va, want, speed),
                     "hz " + std::to_string(hz) + " speed " + std::to_string(speed));
    }
  }
}

}  // namespace
}  // namespace nineball::physics_test
