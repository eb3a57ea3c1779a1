#include <gtest/gtest.h>

#include <string>

#include "nineball/scenes.hpp"
#include "physics/physics_fixtures.hpp"

namespace nineball::physics_test {
namespace {

// Field by field (the golden test hashes the same run): a difference here names the ball or
// the event that moved.
void expectSameBits(const SimResult& a, const SimResult& b, const std::string& what) {
  EXPECT_EQ(a.time, b.time) << what;
  EXPECT_EQ(a.steps, b.steps) << what;
  ASSERT_EQ(a.balls.size(), b.balls.size()) << what;
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    const BallState &x = a.balls[i], &y = b.balls[i];
    EXPECT_EQ(x.id, y.id) << what;
    EXPECT_EQ(x.pos, y.pos) << what << " ball " << x.id;
    EXPECT_EQ(x.vel, y.vel) << what << " ball " << x.id;
    EXPECT_EQ(x.pocket, y.pocket) << what << " ball " << x.id;
  }
  ASSERT_EQ(a.events.size(), b.events.size()) << what;
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    const Event &x = a.events[i], &y = b.events[i];
    const std::string where = what + " event " + std::to_string(i);
    EXPECT_EQ(x.type, y.type) << where;
    EXPECT_EQ(x.t, y.t) << where;
    EXPECT_EQ(x.a, y.a) << where;
    EXPECT_EQ(x.b, y.b) << where;
    EXPECT_EQ(x.va, y.va) << where;
    EXPECT_EQ(x.vb, y.vb) << where;
    if (x.type == EventType::Pocket) {
      EXPECT_EQ(x.pocket, y.pocket) << where;
    }
  }
}

TEST(Determinism, BreakTwiceGivesTheSameBits) {
  const Scene scene = breakScene();
  const SimResult first = simulate(scene);
  const SimResult second = simulate(scene);
  // A break that did nothing would compare equal too.
  EXPECT_GT(countEvents(first.events, EventType::BallBall), 9);
  EXPECT_TRUE(firstEvent(first.events, EventType::AllAtRest).has_value());
  expectSameBits(first, second, "pairwise break");
}

TEST(Determinism, SameBitsWithEveryModel) {
  Scene scene = breakScene(7, 12.0);
  scene.step.box2d.contacts = ContactModel::Box2D;
  scene.physics.cloth = ClothModel::Damping;
  scene.until = 3.0;
  expectSameBits(simulate(scene), simulate(scene), "box2d contacts, damping cloth");
}

TEST(Determinism, WorldsDoNotShareState) {
  // A second world alive at the same time must not change the first one's run.
  const Scene scene = breakScene(3, 10.0);
  const SimResult alone = simulate(scene);
  World other(scene.table, scene.physics, scene.step);
  for (const BallState& b : scene.balls) other.addBall(b);
  other.strike(kCueBall, Shot::withSpeed(45.0, 5.0));
  other.runFor(0.5);
  expectSameBits(alone, simulate(scene), "with a second world");
}

}  // namespace
}  // namespace nineball::physics_test
