// Whatever the shot, every ball ends on the table or in a pocket, with both engines: spinning
// and masse shots (curved sliding paths) were let through the rails by the reference engine.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/limits.hpp"
#include "nineball/random.hpp"
#include "nineball/sim.hpp"

namespace nineball {
namespace {

Scene cueBallScene(Vec2 at, Shot shot, EngineKind engine) {
  Scene s;
  s.balls = {BallState::at(kCueBall, at)};
  s.shot = shot;
  s.step.engine = engine;
  return s;
}

void expectOnTheTable(const Scene& s, const std::string& what) {
  const SimResult r = simulate(s);
  const auto fault = resultFault(s, r);
  EXPECT_FALSE(fault.has_value()) << what << ": " << *fault;
}

TEST(OnTheTable, TheMasseShotThatWentThroughTheRailStaysOnTheTable) {
  Shot shot = Shot::withSpeed(81.50146726146184, 10.422766520861908);
  shot.tip = {-0.23121752481619767, 0.35510525349906796};
  shot.elevation_rad = degToRad(81.90203616341398);
  for (EngineKind engine : {EngineKind::named("box2d"), EngineKind::named("reference")}) {
    const Scene s = cueBallScene({0.02895148154814775, -0.12755246621588656}, shot, engine);
    const SimResult r = simulate(s);
    EXPECT_FALSE(resultFault(s, r).has_value()) << *resultFault(s, r);
    EXPECT_LT(std::abs(r.balls[0].pos.x), 1.3);
  }
}

// Random single balls struck with the most spin the cue gives, at every elevation, and balls
// set moving with spin up to the scene's limit (limits::kMaxSurfaceSpeed): 3 of 300 of the
// latter left the table through the reference engine before the cushion search followed
// curved paths back onto a rail.
TEST(OnTheTable, SpinningBallsStayOnTheTableWithBothEngines) {
  std::uint64_t rng = 2026;
  const PhysicsParams p;
#ifdef NINEBALL_SANITIZED
  constexpr int kShots = 100;
#else
  constexpr int kShots = 600;
#endif
  const double max_spin = limits::kMaxSurfaceSpeed / p.ball_radius;
  for (int i = 0; i < kShots; ++i) {
    const Vec2 at{uniform(rng, -1.2, 1.2), uniform(rng, -0.58, 0.58)};
    Shot shot = Shot::withSpeed(uniform(rng, -180.0, 180.0), uniform(rng, 0.5, 14.0));
    const double a = uniform(rng, 0.0, 2.0 * kPi);
    const double tip = p.miscue_limit * uniform(rng, 0.98, 0.9999);
    shot.tip = {tip * std::cos(a), tip * std::sin(a)};
    shot.elevation_rad = degToRad(uniform(rng, 0.0, 89.0));
    BallState spun = BallState::at(
        kCueBall, at,
        fromAngle(uniform(rng, 0.0, 2.0 * kPi)) * uniform(rng, 0.0, limits::kMaxSpeed));
    spun.w = {uniform(rng, -max_spin, max_spin), uniform(rng, -max_spin, max_spin),
              uniform(rng, -max_spin, max_spin)};
    for (EngineKind engine : {EngineKind::named("box2d"), EngineKind::named("reference")}) {
      expectOnTheTable(cueBallScene(at, shot, engine), "shot " + std::to_string(i));
      Scene s;
      s.balls = {spun};
      s.step.engine = engine;
      expectOnTheTable(s, "spun ball " + std::to_string(i));
    }
  }
}

// A result with a ball outside the cushions is named as a defect, not printed.
TEST(OnTheTable, AResultWithABallOffTheTableIsAFault) {
  const Scene s =
      cueBallScene({0.0, 0.0}, Shot::withSpeed(0.0, 1.0), EngineKind::named("reference"));
  SimResult r = simulate(s);
  EXPECT_FALSE(resultFault(s, r).has_value());
  r.balls[0].pos = {-38.4, 25.9};
  ASSERT_TRUE(resultFault(s, r).has_value());
  EXPECT_NE(resultFault(s, r)->find("ball 0 ended off the table"), std::string::npos);
  r.balls[0].pocket = PocketId::TopLeft;
  EXPECT_FALSE(resultFault(s, r).has_value());
}

}  // namespace
}  // namespace nineball
