// The pocket model of "physics" ("pocket": "fall" or "drop", and "pocket_restitution"):
// accepted, printed back, refused by name where wrong or unused.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "io/scene_checks.hpp"
#include "io/scene_json.hpp"
#include "io/scene_parts.hpp"

namespace nineball::io {
namespace {

std::string pocketScene(const std::string& physics) {
  return R"({"balls": [{"id": 0, "x": -0.5, "y": 0.0}], "physics": {)" + physics + "}}";
}

using testing::accepted;
using testing::refusedAt;

TEST(SceneJsonPocket, TheRealPresetFallsAndThePaperDrops) {
  Scene s = accepted(pocketScene(R"("preset": "real")"));
  EXPECT_EQ(s.physics.pocket, PocketModel::Fall);
  auto out = physicsToJson(s.physics);
  EXPECT_EQ(out["pocket"], "fall");
  EXPECT_EQ(out["pocket_restitution"], s.physics.pocket_restitution);
  s = accepted(pocketScene(R"("preset": "paper")"));
  EXPECT_EQ(s.physics.pocket, PocketModel::Drop);
  out = physicsToJson(s.physics);
  EXPECT_EQ(out["pocket"], "drop");
  EXPECT_FALSE(out.contains("pocket_restitution"));
}

TEST(SceneJsonPocket, AcceptsTheModelAndTheBack) {
  Scene s = accepted(pocketScene(R"("pocket": "drop")"));
  EXPECT_EQ(s.physics.pocket, PocketModel::Drop);
  s = accepted(pocketScene(R"("preset": "paper", "pocket": "fall", "pocket_restitution": 0.8)"));
  EXPECT_EQ(s.physics.pocket, PocketModel::Fall);
  EXPECT_EQ(s.physics.pocket_restitution, 0.8);
  EXPECT_EQ(physicsToJson(s.physics)["pocket_restitution"], 0.8);
}

TEST(SceneJsonPocket, RefusesWhatIsWrongOrUnused) {
  EXPECT_TRUE(
      refusedAt(pocketScene(R"("pocket": "net")"), "physics.pocket", "unknown pocket model"));
  EXPECT_TRUE(refusedAt(pocketScene(R"("pocket": 1)"), "physics.pocket", "expected"));
  EXPECT_TRUE(
      refusedAt(pocketScene(R"("pocket_restitution": 1.5)"), "physics.pocket_restitution", ""));
  EXPECT_TRUE(
      refusedAt(pocketScene(R"("pocket_restitution": -0.1)"), "physics.pocket_restitution", ""));
  EXPECT_TRUE(refusedAt(pocketScene(R"("pocket": "drop", "pocket_restitution": 0.5)"),
                        "physics.pocket_restitution", "not used by the \"drop\" pocket"));
}

}  // namespace
}  // namespace nineball::io
