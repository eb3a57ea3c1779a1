// Every engine of the registry behind one interface: made by name, and a run to rest stepped
// frame by frame (as the window steps a shot) ends bit for bit where one run to rest ends (as
// `nineball match` and the computer's simulations run it), so a rack is the same either way.
#include "nineball/engine.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "nineball/random.hpp"
#include "nineball/scenes.hpp"
#include "nineball/state_hash.hpp"

namespace nineball {
namespace {

std::unique_ptr<Engine> loaded(const Scene& s) {
  auto engine = makeEngine(s.table, s.physics, s.step);
  for (const BallState& b : s.balls) engine->addBall(b);
  return engine;
}

TEST(Engines, EachIsMadeByItsName) {
  const std::vector<std::string> names = EngineKind::names();
  ASSERT_EQ(names, (std::vector<std::string>{"box2d", "reference"}));
  for (const std::string& name : names) {
    StepParams step;
    step.engine = EngineKind::named(name);
    EXPECT_STREQ(step.engine.name(), name.c_str());
    const auto engine = makeEngine(TableDef{}, PhysicsParams{}, step);
    EXPECT_EQ(engine->stepParams().engine, step.engine);
  }
  EXPECT_FALSE(EngineKind::fromName("bullet"));
  EXPECT_THROW(EngineKind::named("bullet"), std::invalid_argument);
}

TEST(Engines, AShotSteppedFrameByFrameEndsWhereARunToRestEnds) {
  std::uint64_t rng = 11;
  for (const std::string& name : EngineKind::names()) {
    for (int shot = 0; shot < 6; ++shot) {
      Scene s = breakScene();
      s.step.engine = EngineKind::named(name);
      const Shot strike = Shot::withSpeed(uniform(rng, -3.0, 3.0), uniform(rng, 2.0, 12.0));
      auto whole = loaded(s);
      whole->strike(kCueBall, strike);
      whole->runUntilRest();
      auto framed = loaded(s);
      framed->strike(kCueBall, strike);
      const double deadline = framed->time() + s.step.max_time;
      int frames = 0;
      while (!framed->stepTowardRest(deadline)) ++frames;
      EXPECT_GT(frames, 10) << name;
      EXPECT_EQ(stateHash(framed->balls()), stateHash(whole->balls())) << name << ", shot " << shot;
      EXPECT_EQ(framed->time(), whole->time()) << name << ", shot " << shot;
      EXPECT_EQ(framed->events().size(), whole->events().size()) << name << ", shot " << shot;
    }
  }
}

TEST(Engines, BothPlaceSpotAndStrikeTheSameWay) {
  for (const std::string& name : EngineKind::names()) {
    Scene s = breakScene();
    s.step.engine = EngineKind::named(name);
    auto engine = loaded(s);
    engine->strike(kCueBall, Shot::withSpeed(0.0, 8.0));
    engine->runUntilRest();
    ASSERT_TRUE(engine->atRest()) << name;
    const Vec2 spot = engine->table().footSpot();
    int dropped = -1;
    for (const BallState& b : engine->balls()) {
      if (b.pocket && b.id != kCueBall) dropped = b.id;
    }
    ASSERT_GE(dropped, 0) << name << ": the break pockets a ball";
    engine->placeBall(dropped, spot);  // a pocketed ball comes back: spotted
    for (const BallState& b : engine->balls()) {
      if (b.id != dropped) continue;
      EXPECT_FALSE(b.pocket) << name;
      EXPECT_EQ(b.pos, spot) << name;
      EXPECT_EQ(b.vel, Vec2{}) << name;
    }
    engine->placeBall(kCueBall, {engine->table().headStringX(), 0.0});
    EXPECT_EQ(engine->balls()[0].pos.x, engine->table().headStringX()) << name;
    EXPECT_FALSE(engine->balls()[0].pocket) << name;
    EXPECT_TRUE(engine->strike(kCueBall, Shot::withSpeed(180.0, 1.0))) << name;
    EXPECT_FALSE(engine->atRest()) << name;
  }
}

}  // namespace
}  // namespace nineball
