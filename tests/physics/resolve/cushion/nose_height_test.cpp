// Every cushion model whose nose is the contact point takes one range of nose heights (the
// ball's centre up to below its top, contact.hpp) and says so in one message; at the ends of
// the range a ball still leaves finite, not into the cushion, with no energy gained.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "nineball/params.hpp"
#include "physics/model/motion.hpp"
#include "physics/resolve/cushion/registry.hpp"

namespace nineball::physics {
namespace {

TEST(NoseHeight, EveryNoseModelTakesTheSameRangeAndBouncesAtItsEnds) {
  for (const char* name : {"mathavan", "stronge", "mathavan_speed"}) {
    PhysicsParams p = PhysicsParams::real();
    p.cushion = CushionModel::named(name);
    const CushionModelDef& model = cushionModel(p.cushion);
    ASSERT_NE(model.check, nullptr) << name;
    ASSERT_NE(model.bounce, nullptr) << name;
    const double r = p.ball_radius;
    for (double h : {r, 1.27 * r, 1.999 * r}) {
      p.cushion_height = h;
      EXPECT_FALSE(model.check(p).has_value()) << name << " at " << h / r << " R";
      // A rolling ball into the rail at 45 degrees, 2 m/s.
      const Vec2 v{std::sqrt(2.0), -std::sqrt(2.0)};
      const Kinematics in{{0.0, 0.0}, v, {v.y / r * -1.0, v.x / r, 0.0}};
      double impulse = 0.0;
      const Kinematics out = model.bounce(in, {0.0, 1.0}, p.ball_mass, p, impulse);
      EXPECT_TRUE(std::isfinite(out.v.x) && std::isfinite(out.v.y) && std::isfinite(out.w.z))
          << name << " at " << h / r << " R";
      EXPECT_GE(out.v.y, 0.0) << name << " at " << h / r << " R: into the cushion";
      EXPECT_LE(kineticEnergy(out, p.ball_mass, r), kineticEnergy(in, p.ball_mass, r) * (1 + 1e-12))
          << name << " at " << h / r << " R";
    }
    for (double h : {0.999 * r, 2.0 * r}) {
      p.cushion_height = h;
      const auto why = model.check(p);
      ASSERT_TRUE(why.has_value()) << name << " at " << h / r << " R";
      EXPECT_EQ(why->rfind("physics.cushion_height: the ", 0), 0u) << *why;
      EXPECT_NE(why->find("no lower than the ball's centre and below its top"), std::string::npos)
          << *why;
    }
  }
}

}  // namespace
}  // namespace nineball::physics
