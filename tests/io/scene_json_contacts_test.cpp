// The contact options of "physics": the speed-dependent cushion and its curve, and the contact
// orders "frozen" and "corner" with cushion_contact_time: accepted, printed back, refused by
// name where they are wrong or unused.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "io/scene_checks.hpp"
#include "io/scene_json.hpp"
#include "io/scene_parts.hpp"

namespace nineball::io {
namespace {

std::string scene(const std::string& physics) {
  return R"({"table": "carom", "balls": [{"id": 0, "x": -0.5, "y": 0.0}, {"id": 1, "x": 0.5, "y": 0.1}], "physics": {)" +
         physics + "}}";
}

using testing::accepted;
using testing::refusedAt;

TEST(SceneJsonContacts, DefaultsAreSequentialAndPrintNothingNew) {
  for (const char* preset : {"real", "paper", "carom"}) {
    const Scene s = accepted(scene(std::string(R"("preset": ")") + preset + "\""));
    EXPECT_EQ(s.physics.frozen, ContactOrder::Sequential);
    EXPECT_EQ(s.physics.corner, ContactOrder::Sequential);
    const auto out = physicsToJson(s.physics);
    for (const char* key :
         {"frozen", "corner", "cushion_contact_time", "cushion_restitution_base"}) {
      EXPECT_FALSE(out.contains(key)) << preset << " " << key;
    }
  }
}

TEST(SceneJsonContacts, AcceptsTheNamesAndFields) {
  Scene s = accepted(scene(
      R"("preset": "carom", "cushion": "mathavan_speed", "cushion_restitution_base": 0.5,
         "cushion_restitution_slope": 0.2, "cushion_restitution_quadratic": -0.05,
         "cushion_restitution_min": 0.3, "frozen": "simultaneous", "corner": "simultaneous",
         "cushion_contact_time": 0.004)"));
  EXPECT_EQ(s.physics.cushion, CushionModel::named("mathavan_speed"));
  EXPECT_EQ(s.physics.cushion_restitution_base, 0.5);
  EXPECT_EQ(s.physics.cushion_restitution_slope, 0.2);
  EXPECT_EQ(s.physics.cushion_restitution_quadratic, -0.05);
  EXPECT_EQ(s.physics.cushion_restitution_min, 0.3);
  EXPECT_EQ(s.physics.frozen, ContactOrder::Simultaneous);
  EXPECT_EQ(s.physics.corner, ContactOrder::Simultaneous);
  EXPECT_EQ(s.physics.cushion_contact_time, 0.004);
  // Printed back, and read again to the same settings.
  const auto out = physicsToJson(s.physics);
  EXPECT_EQ(out["frozen"], "simultaneous");
  EXPECT_EQ(out["corner"], "simultaneous");
  EXPECT_EQ(out["cushion_contact_time"], 0.004);
  EXPECT_EQ(out["cushion_restitution_slope"], 0.2);
  EXPECT_FALSE(out.contains("cushion_restitution"));  // the curve replaces it
  const Scene again = accepted(scene(out.dump().substr(1, out.dump().size() - 2)));
  EXPECT_EQ(physicsToJson(again.physics), out);
  // The defaults of the curve: Han 2005.
  s = accepted(scene(R"("cushion": "mathavan_speed")"));
  EXPECT_EQ(s.physics.cushion_restitution_base, 0.39);
  EXPECT_EQ(s.physics.cushion_restitution_slope, 0.257);
  EXPECT_EQ(s.physics.cushion_restitution_quadratic, -0.044);
  EXPECT_EQ(s.physics.cushion_restitution_min, 0.40);
  EXPECT_EQ(s.physics.cushion_contact_time, 0.01);
  // How near a cushion a struck ball counts as frozen: 0 unless set, printed with the order.
  EXPECT_EQ(s.physics.frozen_tolerance, 0.0);
  s = accepted(scene(R"("frozen": "simultaneous", "frozen_tolerance": 0.003)"));
  EXPECT_EQ(s.physics.frozen_tolerance, 0.003);
  EXPECT_EQ(physicsToJson(s.physics)["frozen_tolerance"], 0.003);
  // Each order alone.
  s = accepted(scene(R"("frozen": "sequential", "corner": "simultaneous")"));
  EXPECT_EQ(s.physics.frozen, ContactOrder::Sequential);
  EXPECT_EQ(s.physics.corner, ContactOrder::Simultaneous);
}

TEST(SceneJsonContacts, RefusesBadValuesByName) {
  EXPECT_TRUE(refusedAt(scene(R"("frozen": "together")"), "physics.frozen",
                        "unknown frozen model \"together\" (expected \"sequential\" or "
                        "\"simultaneous\")"));
  EXPECT_TRUE(refusedAt(scene(R"("corner": 1)"), "physics.corner", "expected a string"));
  EXPECT_TRUE(refusedAt(scene(R"("corner": "simultaneous", "cushion_contact_time": 0)"),
                        "physics.cushion_contact_time", ""));
  EXPECT_TRUE(refusedAt(scene(R"("corner": "simultaneous", "cushion_contact_time": 0.2)"),
                        "physics.cushion_contact_time", ""));
  EXPECT_TRUE(refusedAt(scene(R"("cushion": "mathavan_speed", "cushion_restitution_base": 1.5)"),
                        "physics.cushion_restitution_base", ""));
  EXPECT_TRUE(refusedAt(scene(R"("cushion": "mathavan_speed", "cushion_restitution_slope": -2)"),
                        "physics.cushion_restitution_slope", ""));
  EXPECT_TRUE(
      refusedAt(scene(R"("cushion": "mathavan_speed", "cushion_restitution_quadratic": 1.01)"),
                "physics.cushion_restitution_quadratic", ""));
  EXPECT_TRUE(refusedAt(scene(R"("cushion": "mathavan_speed", "cushion_restitution_min": -0.1)"),
                        "physics.cushion_restitution_min", ""));
  EXPECT_TRUE(refusedAt(scene(R"("cushion": "flubber")"), "physics.cushion", "mathavan_speed"));
}

TEST(SceneJsonContacts, RefusesABadFrozenTolerance) {
  EXPECT_TRUE(refusedAt(scene(R"("frozen_tolerance": 0.002)"), "physics.frozen_tolerance",
                        "not used by the \"sequential\" frozen ball"));
  EXPECT_TRUE(refusedAt(scene(R"("frozen": "simultaneous", "frozen_tolerance": -0.001)"),
                        "physics.frozen_tolerance", ""));
  EXPECT_TRUE(refusedAt(scene(R"("frozen": "simultaneous", "frozen_tolerance": 0.05)"),
                        "physics.frozen_tolerance", ""));
}

TEST(SceneJsonContacts, RefusesUnusedParametersByName) {
  EXPECT_TRUE(refusedAt(scene(R"("cushion_contact_time": 0.005)"), "physics.cushion_contact_time",
                        "not used by the \"sequential\" corner"));
  EXPECT_TRUE(refusedAt(scene(R"("corner": "sequential", "cushion_contact_time": 0.005)"),
                        "physics.cushion_contact_time", "not used"));
  EXPECT_TRUE(refusedAt(scene(R"("cushion_restitution_slope": 0.1)"),
                        "physics.cushion_restitution_slope",
                        "not used by the \"mathavan\" cushion (only by \"mathavan_speed\")"));
  EXPECT_TRUE(refusedAt(scene(R"("cushion": "simple", "cushion_restitution_min": 0.1)"),
                        "physics.cushion_restitution_min", "not used by the \"simple\" cushion"));
  EXPECT_TRUE(refusedAt(scene(R"("cushion": "mathavan_speed", "cushion_restitution": 0.9)"),
                        "physics.cushion_restitution",
                        "not used by the \"mathavan_speed\" cushion"));
  // Wherever the choice appears in the object.
  EXPECT_TRUE(refusedAt(scene(R"("cushion_contact_time": 0.005, "corner": "sequential")"),
                        "physics.cushion_contact_time", "not used"));
  accepted(scene(R"("cushion_contact_time": 0.005, "corner": "simultaneous")"));
  accepted(scene(R"("cushion_restitution_min": 0.5, "cushion": "mathavan_speed")"));
  // The unknown-parameter list names the new fields.
  EXPECT_TRUE(refusedAt(scene(R"("frozn": "simultaneous")"), "physics.frozn",
                        "frozen, corner, cushion_contact_time"));
}

}  // namespace
}  // namespace nineball::io
