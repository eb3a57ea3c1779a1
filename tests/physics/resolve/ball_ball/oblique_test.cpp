#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "physics/physics_fixtures.hpp"
#include "support/paper_figures.hpp"

namespace nineball::physics_test {
namespace {

using testing::kPrintedRounding;

struct CutShot {
  Event hit;
  Vec2 u;  // cue-ball velocity just before the contact
};

// Cue ball along +x into a resting object ball at the origin, its centre line offset by
// b = 2R sin(cut) so that the line of centres at contact makes `cut` with +x.
CutShot cutShot(const PhysicsParams& p, double cut_deg, double speed,
                const StepParams& sp = StepParams{}) {
  const double offset = 2.0 * p.ball_radius * std::sin(degToRad(cut_deg));
  auto world =
      makeWorld(longTable(), p, sp,
                {makeBall(kCueBall, {-0.4, -offset}, {speed, 0.0}), makeBall(1, {0.0, 0.0})});
  const auto hit = runUntilEvent(*world, EventType::BallBall, 2.0);
  EXPECT_TRUE(hit.has_value()) << "cut " << cut_deg << " speed " << speed;
  if (!hit) return {};
  EXPECT_EQ(hit->a, kCueBall);
  EXPECT_EQ(hit->b, 1);
  // The cloth's constant deceleration up to the contact (zero when frictionless).
  const double u = speed - p.rolling_friction * p.gravity * hit->t;
  return {*hit, {u, 0.0}};
}

// Paper eq. 2.27-2.65 for a resting object ball and equal masses: along n the 1-D formula,
// across n nothing changes.
void formula(Vec2 u, double cut_deg, double e, Vec2& cue, Vec2& object) {
  const Vec2 n = fromAngle(degToRad(cut_deg));
  object = n * ((1.0 + e) / 2.0 * dot(u, n));
  cue = u - object;
}

TEST(Oblique, PaperThirtyDegreeExample) {
  // Bourg's example as the paper gives it: 6.1 cm balls of 156 g, e = 1, 10 m/s along x.
  PhysicsParams p = frictionless();
  p.ball_radius = 0.061 / 2.0;
  p.ball_mass = 0.156;
  p.ball_restitution = 1.0;
  const CutShot shot = cutShot(p, 30.0, 10.0);
  const Vec2 v1 = shot.hit.va, v2 = shot.hit.vb;
  EXPECT_NEAR(length(v2), 8.66, kPrintedRounding);
  EXPECT_NEAR(length(v1), 5.0, kPrintedRounding);
  EXPECT_NEAR(radToDeg(std::atan2(v2.y, v2.x)), 30.0, kDirectionToleranceDeg);
  EXPECT_NEAR(angleBetweenDeg(v1, v2), 90.0, kDirectionToleranceDeg);
  EXPECT_LE(relativeError(length(v2), 10.0 * std::cos(degToRad(30.0)), 10.0),
            kCollisionSpeedTolerance);
  EXPECT_LE(relativeError(length(v1), 10.0 * std::sin(degToRad(30.0)), 10.0),
            kCollisionSpeedTolerance);
}

TEST(Oblique, CutSweepFollowsTheLineOfCentres) {
  WorstError direction("cut sweep: object-ball direction", kDirectionToleranceDeg, "deg");
  WorstError separation("cut sweep: 90-degree rule (e = 1)", kDirectionToleranceDeg, "deg");
  WorstError velocity("cut sweep: velocities after", kCollisionSpeedTolerance);
  // 8 and 16 m/s travel more than 1.5 Box2D units in a 500 Hz step: the world sub-steps them.
  for (double speed : {0.5, 3.0, 8.0, 16.0}) {
    for (double e : {1.0, 0.95}) {
      PhysicsParams p = frictionless();
      p.ball_restitution = e;
      for (int cut = 0; cut <= 80; cut += 10) {
        const std::string where = "speed " + std::to_string(speed) + " e " + std::to_string(e) +
                                  " cut " + std::to_string(cut);
        const CutShot shot = cutShot(p, cut, speed);
        const Vec2 vb = shot.hit.vb;
        direction.check(std::abs(radToDeg(std::atan2(vb.y, vb.x)) - cut), where);
        Vec2 want_cue, want_object;
        formula(shot.u, cut, e, want_cue, want_object);
        velocity.check(vectorError(shot.hit.va, want_cue, speed), where + " cue ball");
        velocity.check(vectorError(vb, want_object, speed), where + " object ball");
        if (e == 1.0 && cut > 0) {
          separation.check(std::abs(angleBetweenDeg(shot.hit.va, vb) - 90.0), where);
        }
      }
    }
  }
}

TEST(Oblique, CutSweepWithClothFrictionAndSlowSteps) {
  // The real cloth slows the cue ball on its way in; the formula is applied to the speed it
  // has at the contact, v0 - mu g t. A 120 Hz step makes the world sub-step and split steps.
  WorstError direction("cut sweep with cloth: object-ball direction", kDirectionToleranceDeg,
                       "deg");
  WorstError velocity("cut sweep with cloth: velocities after", kCollisionSpeedTolerance);
  const PhysicsParams p = constantDeceleration();
  for (double hz : {500.0, 120.0}) {
    StepParams sp;
    sp.hz = hz;
    for (double speed : {0.5, 3.0, 12.0}) {
      for (int cut = 0; cut <= 80; cut += 10) {
        const std::string where = "hz " + std::to_string(hz) + " speed " + std::to_string(speed) +
                                  " cut " + std::to_string(cut);
        const CutShot shot = cutShot(p, cut, speed, sp);
        const Vec2 vb = shot.hit.vb;
        direction.check(std::abs(radToDeg(std::atan2(vb.y, vb.x)) - cut), where);
        Vec2 want_cue, want_object;
        formula(shot.u, cut, p.ball_restitution, want_cue, want_object);
        velocity.check(vectorError(shot.hit.va, want_cue, speed), where + " cue ball");
        velocity.check(vectorError(vb, want_object, speed), where + " object ball");
      }
    }
  }
}

TEST(Oblique, HalfBallHitSendsTheObjectBallThirtyDegreesOff) {
  // Centre offset R (a "half-ball hit"): the object ball leaves 30 degrees off the cue line.
  const PhysicsParams p = constantDeceleration();
  const double offset = p.ball_radius;
  auto world = makeWorld(longTable(), p, StepParams{},
                         {makeBall(kCueBall, {-0.4, offset}, {2.0, 0.0}), makeBall(1, {0.0, 0.0})});
  const auto hit = runUntilEvent(*world, EventType::BallBall, 2.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(radToDeg(std::atan2(hit->vb.y, hit->vb.x)), -30.0, kDirectionToleranceDeg);
}

}  // namespace
}  // namespace nineball::physics_test
