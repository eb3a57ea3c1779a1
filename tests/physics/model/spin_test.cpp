// The spin model against the closed forms players know (paper chapter 3 and the billiards
// literature). Tolerances: 0.5 % on speeds and distances, as the targets for the
// physics core; 0.1 degree on directions. Times are found to within one step of the world.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/model/motion.hpp"
#include "physics/physics_fixtures.hpp"

using namespace nineball;
using namespace nineball::physics_test;

namespace {

constexpr double kSpeedTolerance = 0.005;   // relative, the 0.5 % target
constexpr double kAngleToleranceDeg = 0.1;  // the direction target

// The real preset without rolling resistance, so that a rolling ball keeps its speed and the
// sliding phase can be read off cleanly; and with frictionless balls, which the closed forms
// tested here assume (throw is tested on its own, in models/throw_test.cpp).
PhysicsParams spinOnly(double e = 1.0) {
  PhysicsParams p = PhysicsParams::real();
  p.ball_ball = BallBallModel::named("frictionless");
  p.rolling_friction = 0.0;
  p.spin_decay = 0.0;
  p.ball_restitution = e;
  return p;
}

StepParams fine() {
  StepParams s;
  s.hz = 2000.0;
  return s;
}

std::unique_ptr<World> newWorld(const TableDef& t, const PhysicsParams& p, const StepParams& s) {
  return std::make_unique<World>(t, p, s);
}

double slipOf(const BallState& b, double r) {
  return length(physics::slip(b.vel, b.w, r));
}

const Event* firstBallHit(const World& w) {
  for (const Event& e : w.events()) {
    if (e.type == EventType::BallBall) return &e;
  }
  return nullptr;
}

}  // namespace

TEST(Spin, CentreHitSlidesThenRollsAtFiveSevenths) {
  for (double v0 : {1.0, 3.0, 6.0}) {
    const PhysicsParams p = spinOnly();
    auto w = newWorld(longTable(), p, fine());
    // Near the origin: Box2D keeps positions in single precision, and far out the rounding of
    // every step's small move adds up.
    w->addBall(makeBall(0, {-5.0, 0.0}));
    w->strike(0, Shot::withSpeed(0.0, v0));
    const double mu_g = p.sliding_friction * p.gravity;
    const double t_roll = 2.0 * v0 / (7.0 * mu_g);
    const double d_roll = 12.0 * v0 * v0 / (49.0 * mu_g);
    double seen_roll = -1.0;
    while (w->time() < t_roll + 1.0) {
      w->step();
      if (seen_roll < 0.0 && slipOf(w->balls()[0], p.ball_radius) < 1e-6) seen_roll = w->time();
    }
    const BallState b = w->balls()[0];
    EXPECT_NEAR(b.vel.x, 5.0 / 7.0 * v0, kSpeedTolerance * v0) << v0;
    EXPECT_NEAR(b.w.y, b.vel.x / p.ball_radius, 1e-9 * v0 / p.ball_radius) << v0;
    // Rolling since t_roll at 5/7 v0: where it is now says where rolling began.
    const double want_x = -5.0 + d_roll + 5.0 / 7.0 * v0 * (w->time() - t_roll);
    EXPECT_NEAR(b.pos.x, want_x, kSpeedTolerance * d_roll) << v0;
    EXPECT_NEAR(seen_roll, t_roll, 1.0 / fine().hz) << v0;
  }
}

TEST(Spin, HitTwoFifthsAboveCentreRollsAtOnce) {
  const PhysicsParams p = spinOnly();
  auto w = newWorld(longTable(), p, fine());
  w->addBall(makeBall(0, {-25.0, 0.0}));
  Shot s = Shot::withSpeed(0.0, 2.0);
  s.tip = {0.0, 0.4};
  w->strike(0, s);
  EXPECT_LT(slipOf(w->balls()[0], p.ball_radius), 1e-12);
  w->runFor(1.0);
  EXPECT_NEAR(w->balls()[0].vel.x, 2.0, 1e-9);
}

TEST(Spin, StunShotStopsTheCueBallButForItsShare) {
  for (double e : {1.0, 0.95}) {
    const PhysicsParams p = spinOnly(e);
    auto w = newWorld(longTable(), p, fine());
    const double r = p.ball_radius, v = 2.0;
    // Struck at the centre a hair before the contact: still sliding, no spin, at impact.
    w->addBall(makeBall(0, {-2.0 * r - 0.0005, 0.0}));
    w->addBall(makeBall(1, {0.0, 0.0}));
    w->strike(0, Shot::withSpeed(0.0, v));
    w->runFor(0.01);
    const Event* hit = firstBallHit(*w);
    ASSERT_NE(hit, nullptr);
    EXPECT_NEAR(hit->va.x, (1.0 - e) / 2.0 * v, kSpeedTolerance * v) << e;
    w->runFor(2.0);
    // What it keeps then slides into a roll at 5/7 of itself.
    EXPECT_NEAR(w->balls()[0].vel.x, 5.0 / 7.0 * (1.0 - e) / 2.0 * v, kSpeedTolerance * v) << e;
  }
}

TEST(Spin, RollingFullHitFollowsAtTheClosedForm) {
  for (double e : {1.0, 0.95, 0.9}) {
    const PhysicsParams p = spinOnly(e);
    auto w = newWorld(longTable(), p, fine());
    const double r = p.ball_radius, v = 2.0;
    BallState cue = makeBall(0, {-0.3, 0.0}, {v, 0.0});
    cue.w = {0.0, v / r, 0.0};
    w->addBall(cue);
    w->addBall(makeBall(1, {0.0, 0.0}));
    w->runFor(2.0);
    const double want = 5.0 / 7.0 * (1.0 - e) / 2.0 * v + 2.0 / 7.0 * v;
    EXPECT_NEAR(w->balls()[0].vel.x, want, kSpeedTolerance * v) << e;
  }
}

TEST(Spin, DrawShotComesBack) {
  const PhysicsParams p = PhysicsParams::real();
  auto w = newWorld(TableDef{}, p, StepParams{});
  w->addBall(makeBall(0, {-0.5, 0.0}));
  w->addBall(makeBall(1, {0.0, 0.0}));
  Shot s = Shot::withSpeed(0.0, 2.5);
  s.tip = {0.0, -0.4};
  w->strike(0, s);
  w->runFor(0.5);
  ASSERT_NE(firstBallHit(*w), nullptr);
  double min_vx = 0.0;
  while (!w->atRest()) {
    w->step();
    min_vx = std::min(min_vx, w->balls()[0].vel.x);
  }
  EXPECT_LT(min_vx, -0.2);               // it came back
  EXPECT_LT(w->balls()[0].pos.x, -0.1);  // and ended well behind the contact point
}

TEST(Spin, HalfBallHitDeflectsAboutThirtyThreeDegrees) {
  // The players' 30-degree rule: a rolling cue ball on a half-ball hit ends deflected by
  // arctan(sin a cos a / (sin^2 a + 2/5)) from its line, a = 30 degrees: 33.7 degrees.
  const PhysicsParams p = spinOnly(1.0);
  for (double cut_deg : {15.0, 30.0, 45.0}) {
    auto w = newWorld(longTable(), p, fine());
    const double r = p.ball_radius, v = 2.0;
    const double a = degToRad(cut_deg);
    BallState cue = makeBall(0, {-0.3, 0.0}, {v, 0.0});
    cue.w = {0.0, v / r, 0.0};
    w->addBall(cue);
    w->addBall(makeBall(1, {0.0, -2.0 * r * std::sin(a)}));
    w->runFor(0.6);  // sliding is over by 0.3 s; the side cushions are still far
    const Vec2 out = w->balls()[0].vel;
    const double got = radToDeg(std::atan2(out.y, out.x));
    const double want =
        radToDeg(std::atan(std::sin(a) * std::cos(a) / (std::sin(a) * std::sin(a) + 0.4)));
    EXPECT_NEAR(got, want, kAngleToleranceDeg) << cut_deg;
    if (cut_deg == 30.0) {
      EXPECT_NEAR(got, 33.67, 0.01);
    }
  }
}

TEST(Spin, SideSpinChangesTheAngleOffACushion) {
  // A ball sent up-right into the top cushion: right english runs along the rail (wider
  // angle off it), left english checks it (narrower), none sits between.
  auto reboundAngle = [](double side) {
    PhysicsParams p = PhysicsParams::real();
    p.cue_end_mass = 0.0;  // no squirt: the same path in, so that only the spin differs
    auto w = newWorld(TableDef{}, p, StepParams{});
    w->addBall(makeBall(0, {-0.6, 0.3}));
    Shot s = Shot::withSpeed(45.0, 2.0);
    s.tip = {side, 0.0};
    w->strike(0, s);
    while (w->balls()[0].vel.y >= 0.0) w->step();
    w->runFor(0.02);
    const Vec2 v = w->balls()[0].vel;
    return radToDeg(std::atan2(v.x, -v.y));  // from the cushion's normal
  };
  const double running = reboundAngle(0.4), plain = reboundAngle(0.0), reverse = reboundAngle(-0.4);
  EXPECT_GT(running, plain + 2.0);
  EXPECT_LT(reverse, plain - 2.0);
}

TEST(Spin, MiscueIsReportedNotPlayed) {
  auto w = newWorld(TableDef{}, PhysicsParams::real(), StepParams{});
  w->addBall(makeBall(0, {-0.5, 0.0}));
  Shot s = Shot::withSpeed(0.0, 2.0);
  s.tip = {0.4, 0.35};  // |tip| = 0.53 > 0.5
  EXPECT_FALSE(w->strike(0, s));
  ASSERT_EQ(w->events().size(), 1u);
  EXPECT_EQ(w->events()[0].type, EventType::Miscue);
  EXPECT_TRUE(w->atRest());
  s.tip = {0.3, 0.35};  // 0.46: a hit
  EXPECT_TRUE(w->strike(0, s));
  EXPECT_FALSE(w->atRest());
}

TEST(Spin, PaperPresetHasNoSpin) {
  auto w = newWorld(TableDef{}, PhysicsParams::paper(), StepParams{});
  w->addBall(makeBall(0, {-0.5, 0.0}));
  Shot s = Shot::withSpeed(0.0, 2.0);
  s.tip = {0.3, -0.3};
  w->strike(0, s);
  w->step();
  const BallState b = w->balls()[0];
  EXPECT_EQ(b.w, Vec3{});
  // mu m g only: the speed falls by rolling_friction g per second, nothing more.
  const PhysicsParams p = PhysicsParams::paper();
  EXPECT_NEAR(b.vel.x, 2.0 - p.rolling_friction * p.gravity / StepParams{}.hz, 1e-6);
}
