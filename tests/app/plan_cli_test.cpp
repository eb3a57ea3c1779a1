// The `nineball plan` contract, run through the real binary.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"

using nineball::testing::CliOutcome;
using nineball::testing::runOnDocument;

namespace {

// The 1 a little off the top-right corner, the cue ball on the line behind it.
const char* kStraightIn = R"({
  "level": "medium",
  "balls": [{"id": 0, "x": 0.4, "y": 0.1}, {"id": 1, "x": 1.0, "y": 0.45},
            {"id": 5, "x": -0.8, "y": -0.3}]
})";

bool pockets(const nlohmann::json& sim_result, int ball) {
  for (const auto& e : sim_result["events"]) {
    if (e["type"] == "pocket" && e["ball"] == ball) return true;
  }
  return false;
}

// The plan's printed `shot` played with `nineball sim` in the planned scene (its "level"
// dropped): the result document; a failed sim fails the test.
nlohmann::json playedWithSim(const char* plan_scene, const nlohmann::json& shot) {
  auto scene = nlohmann::json::parse(plan_scene);
  scene.erase("level");
  scene["shot"] = shot;
  const CliOutcome sim = runOnDocument("sim", scene.dump());
  EXPECT_EQ(sim.status, 0) << sim.err;
  return sim.status == 0 ? nlohmann::json::parse(sim.out) : nlohmann::json::object();
}

}  // namespace

TEST(PlanCli, PrintsAShotThatSimPotsTheBallOnWith) {
  const CliOutcome r = runOnDocument("plan", kStraightIn);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto shot = nlohmann::json::parse(r.out);
  ASSERT_TRUE(shot.contains("heading_deg"));
  ASSERT_TRUE(shot.contains("speed"));
  ASSERT_TRUE(shot.contains("tip"));
  EXPECT_FALSE(shot.contains("cue"));
  // The printed object is a scene's "shot": play it with `nineball sim`.
  const nlohmann::json result = playedWithSim(kStraightIn, shot);
  ASSERT_TRUE(result.contains("events"));
  EXPECT_TRUE(pockets(result, 1));
  EXPECT_FALSE(pockets(result, 0));
}

// The 2 on the cue ball's line to the 1, which is on its line to the top-right corner: master
// jumps it, and the printed shot carries the cue's elevation, so that sim plays the jump.
TEST(PlanCli, AJumpPlanCarriesItsElevation) {
  const char* blocked = R"({
    "level": "master",
    "balls": [{"id": 0, "x": -0.2, "y": -0.35}, {"id": 2, "x": 0.12, "y": -0.15},
              {"id": 1, "x": 0.75, "y": 0.24}, {"id": 3, "x": 0.55, "y": 0.45},
              {"id": 4, "x": 0.95, "y": 0.05}, {"id": 9, "x": -0.9, "y": 0.4}]
  })";
  const CliOutcome r = runOnDocument("plan", blocked);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto shot = nlohmann::json::parse(r.out);
  ASSERT_TRUE(shot.contains("elevation_deg")) << r.out;
  EXPECT_GE(shot["elevation_deg"].get<double>(), 25.0);
  const nlohmann::json result = playedWithSim(blocked, shot);
  ASSERT_TRUE(result.contains("events"));
  EXPECT_TRUE(pockets(result, 1));
  // And a level plan says nothing of the elevation.
  const CliOutcome level = runOnDocument("plan", kStraightIn);
  EXPECT_FALSE(nlohmann::json::parse(level.out).contains("elevation_deg")) << level.out;
}

// Three-cushion: the shot for the white (player A's, the game's first to play) that scores as
// intended, checked by playing it through `nineball match` from the same balls.
TEST(PlanCli, AThreeCushionPlanScoresAPointAsIntended) {
  const std::string balls = R"([{"id": 0, "x": -0.9, "y": 0.3}, {"id": 1, "x": 0.2, "y": -0.25},
                                {"id": 2, "x": 0.8, "y": 0.4}])";
  const CliOutcome r = runOnDocument(
      "plan", R"({"game": "three-cushion", "table": "carom", "physics": {"preset": "carom"},
                  "level": "club", "balls": )" +
                  balls + "}");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto shot = nlohmann::json::parse(r.out);
  ASSERT_TRUE(shot.contains("heading_deg") && shot.contains("speed") && shot.contains("tip"));
  EXPECT_FALSE(shot.contains("cue"));
  const CliOutcome m = runOnDocument("match", R"({"game": "three-cushion", "balls": )" + balls +
                                                  R"(, "turns": [)" + shot.dump() + "]}");
  ASSERT_EQ(m.status, 0) << m.err;
  const auto turn = nlohmann::json::parse(m.out)["turns"][0];
  EXPECT_EQ(turn["point"], true) << m.out;
  EXPECT_GE(turn["cushions"].get<int>(), 3);
}

TEST(PlanCli, PlacesTheCueBallWithBallInHand) {
  const CliOutcome r = runOnDocument("plan", R"({
    "level": "easy", "rules": "wpa", "ball_in_hand": true,
    "balls": [{"id": 3, "x": 0.3, "y": -0.2}, {"id": 9, "x": -0.5, "y": 0.3}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto shot = nlohmann::json::parse(r.out);
  ASSERT_TRUE(shot.contains("cue"));
  const double x = shot["cue"][0], y = shot["cue"][1];
  EXPECT_LT(std::abs(x), 1.27 - 0.028);
  EXPECT_LT(std::abs(y), 0.635 - 0.028);
  for (auto [bx, by] : {std::pair{0.3, -0.2}, std::pair{-0.5, 0.3}}) {
    EXPECT_GE(std::hypot(x - bx, y - by), 2 * 0.028575);
  }
}

TEST(PlanCli, ATenBallPlanCarriesItsCallAndSimPotsTheBallAsCalled) {
  auto scene = nlohmann::json::parse(kStraightIn);
  scene["game"] = "ten-ball";
  scene["balls"][2]["id"] = 10;
  const CliOutcome r = runOnDocument("plan", scene.dump());
  ASSERT_EQ(r.status, 0) << r.err;
  auto shot = nlohmann::json::parse(r.out);
  ASSERT_TRUE(shot.contains("call")) << r.out;
  EXPECT_EQ(shot["call"]["ball"], 1);
  EXPECT_EQ(shot["call"]["pocket"], "top-right");
  scene.erase("level");
  scene.erase("game");
  shot.erase("call");
  scene["shot"] = shot;
  const CliOutcome sim = runOnDocument("sim", scene.dump());
  ASSERT_EQ(sim.status, 0) << sim.err;
  const auto result = nlohmann::json::parse(sim.out);
  for (const auto& e : result["events"]) {
    if (e["type"] == "pocket" && e["ball"] == 1) {
      EXPECT_EQ(e["pocket"], "top-right");
    }
  }
  EXPECT_TRUE(pockets(result, 1));
}

TEST(PlanCli, AnEightBallPlanOnAnOpenTableNeverAimsAtTheEight) {
  auto scene = nlohmann::json::parse(kStraightIn);
  scene["game"] = "eight-ball";
  scene["balls"][1]["id"] = 8;   // the hanger is the 8 ...
  scene["balls"][2]["id"] = 12;  // ... and the 12 is the only ball that may be hit
  const CliOutcome r = runOnDocument("plan", scene.dump());
  ASSERT_EQ(r.status, 0) << r.err;
  auto shot = nlohmann::json::parse(r.out);
  EXPECT_FALSE(shot.contains("call"));
  scene.erase("level");
  scene.erase("game");
  scene["shot"] = shot;
  const CliOutcome sim = runOnDocument("sim", scene.dump());
  ASSERT_EQ(sim.status, 0) << sim.err;
  const auto result = nlohmann::json::parse(sim.out);
  for (const auto& e : result["events"]) {
    if (e["type"] != "ball") continue;
    EXPECT_TRUE(e["a"] == 12 || e["b"] == 12) << "the cue ball's first contact: " << e.dump();
    break;
  }
}

TEST(PlanCli, RefusesBadScenesWithStatus2AndNothingOnStdout) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"balls\": [", "invalid JSON"},
      {R"({"balls": [{"id": 0, "x": 0, "y": 0}, {"id": 1, "x": 0.5, "y": 0}], "colour": 1})",
       "colour: unknown field"},
      {R"({"balls": [{"id": 0, "x": 0, "y": 0}, {"id": 1, "x": 0.5, "y": 0}], "level": "grandmaster"})",
       "level: unknown level"},
      {R"({"balls": [{"id": 0, "x": 0, "y": 0}, {"id": 1, "x": 0.5, "y": 0}], "rules": "8"})",
       "rules: unknown rules"},
      {R"({"balls": [{"id": 0, "x": 0, "y": 0}], "ball_in_hand": 1})", "ball_in_hand"},
      {R"({"balls": [{"id": 0, "x": 0, "y": 0}]})", "balls: no object ball"},
      {R"({"balls": [{"id": 1, "x": 0, "y": 0}]})", "balls: needs a cue ball"},
      {R"({"balls": [{"id": 0, "x": "a", "y": 0}, {"id": 1, "x": 0.5, "y": 0}]})",
       "balls[0].x: expected a number"},
      {R"({"balls": [{"id": 0, "x": 0, "y": 0}, {"id": 1, "x": 0.5, "y": 0}], "game": "pool"})",
       "game: unknown game \"pool\""},
      {R"({"balls": [{"id": 0, "x": 0, "y": 0}, {"id": 11, "x": 0.5, "y": 0}],
           "game": "ten-ball"})",
       "balls: ten-ball has no ball 11 (1-10)"},
      {R"({"balls": [{"id": 0, "x": 0, "y": 0}, {"id": 1, "x": 0.5, "y": 0}],
           "game": "eight-ball", "rules": "paper"})",
       "rules: the paper's rules are nine-ball's only"},
  };
  for (const auto& [text, reason] : cases) {
    const CliOutcome r = runOnDocument("plan", text);
    EXPECT_EQ(r.status, 2) << text;
    EXPECT_TRUE(r.out.empty()) << text;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
    EXPECT_EQ(r.err.rfind("nineball plan: ", 0), 0u) << r.err;
  }
}
