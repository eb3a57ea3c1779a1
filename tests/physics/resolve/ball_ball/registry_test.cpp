// Ball-ball models are chosen by name from one registry: names, the parser's list, which model
// reads "ball_friction", and the grip each adds all come from its one line there.
#include "physics/resolve/ball_ball/registry.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace nineball::physics {
namespace {

TEST(BallBallModels, EachIsMadeByItsNameAndSaysWhatItReads) {
  ASSERT_EQ(BallBallModel::names(), (std::vector<std::string>{"frictionless", "frictional"}));
  for (const std::string& name : BallBallModel::names()) {
    const BallBallModel m = BallBallModel::named(name);
    EXPECT_STREQ(m.name(), name.c_str());
    EXPECT_EQ(BallBallModel::fromName(name), m);
    EXPECT_EQ(m.reads("ball_friction"), ballBallModel(m).grip != nullptr) << name;
  }
  EXPECT_FALSE(BallBallModel::fromName("sticky"));
  EXPECT_THROW(BallBallModel::named("sticky"), std::invalid_argument);
  EXPECT_EQ(PhysicsParams{}.ball_ball, BallBallModel::named("frictional"));
  EXPECT_EQ(PhysicsParams::paper().ball_ball, BallBallModel::named("frictionless"));
}

TEST(BallBallModels, OnlyTheFrictionalGripThrowsTheObjectBall) {
  const PhysicsParams p;
  // A half-ball cut: the cue ball slides across the object ball's contact point.
  for (const std::string& name : BallBallModel::names()) {
    const BallBallModelDef& def = ballBallModel(BallBallModel::named(name));
    Kinematics a{{0.0, 0.0}, {1.0, 1.0}, {}};
    Kinematics b{{0.05, 0.0}, {}, {}};
    if (def.grip) def.grip(a, b, p.ball_mass, p.ball_mass, {1.0, 0.0}, 0.1, p);
    EXPECT_EQ(b.v.y != 0.0, def.grip != nullptr) << name;
  }
}

}  // namespace
}  // namespace nineball::physics
