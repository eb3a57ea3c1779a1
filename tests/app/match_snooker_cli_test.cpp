// Snooker through `nineball match` and `nineball plan`, run through the real binary. The scripts
// name the game only and get its own equipment: the "snooker" table and physics preset.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_runner.hpp"

using nineball::testing::CliOutcome;
using nineball::testing::runOnDocument;

namespace {

const std::string kEquipment = R"("game": "snooker")";

std::string script(const std::string& rest) {
  return "{" + kEquipment + ", " + rest + "}";
}

TEST(MatchSnookerCli, ATurnCarriesTheScoreTheBreakAndTheChoices) {
  const CliOutcome r =
      runOnDocument("match", script(R"("turns": [{"heading_deg": 0, "speed": 6, "cue": [-1.1, 0.1]},
                                   {"heading_deg": 90, "speed": 0.2},
                                   {"decision": "replace"}])"));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  const auto& miss = doc["turns"][1];
  EXPECT_EQ(miss["foul"], "no-contact");
  EXPECT_EQ(miss["miss"], true);
  EXPECT_EQ(miss["penalty"], 4);
  EXPECT_EQ(miss["points_remaining"], 147);
  EXPECT_EQ(miss["choices"], nlohmann::json::parse(R"(["play", "put-back", "replace"])"));
  EXPECT_EQ(miss["score"]["A"]["points"], 4);
  EXPECT_EQ(doc["turns"][2]["decision"], "replace");
  EXPECT_EQ(doc["turns"][2]["next"], "B");  // the offender plays it again
  EXPECT_EQ(doc["snookers_required"]["B"], false);
}

TEST(MatchSnookerCli, BadSnookerTurnsAreRefusedByName) {
  const std::pair<std::string, const char*> cases[] = {
      {script(R"("turns": [{"heading_deg": 0, "speed": 6}])"),
       "turns[0]: the cue ball is in hand in the D"},
      {script(R"("turns": [{"heading_deg": 0, "speed": 6, "cue": [-0.5, 0.0]}])"),
       "turns[0]: the cue ball in hand goes in the D (x <= -1.0475, within 0.2920 m of (-1.0475, "
       "0))"},
      {script(
           R"("turns": [{"heading_deg": 0, "speed": 6, "cue": [-1.1, 0.1]}, {"decision": "shoot"}])"),
       "turns[1].decision: expected \"play\" or \"put-back\""},
      {script(R"("points": 50, "turns": [])"), "points: snooker"},
      {script(R"("turns": [{"heading_deg": 0, "speed": 6, "cue": [-1.1, 0.1]},
                           {"heading_deg": 90, "speed": 0.2}, {"heading_deg": 0, "speed": 1}])"),
       "turns[2]: the foul waits for the opponent's decision"},
      {script(
           R"("turns": [{"heading_deg": 0, "speed": 6, "cue": [-1.1, 0.1], "call": {"ball": 22, "pocket": "top-left"}}])"),
       "turns[0].call.ball"},
  };
  for (const auto& [doc, message] : cases) {
    const CliOutcome r = runOnDocument("match", doc);
    EXPECT_EQ(r.status, 2) << doc;
    EXPECT_TRUE(r.out.empty()) << doc;
    EXPECT_NE(r.err.find(message), std::string::npos) << doc << "\n" << r.err;
  }
}

// The plan aims at a ball on: played through the match it hits a red first.
TEST(MatchSnookerCli, APlanHitsABallOnFirst) {
  const std::string balls = R"([{"id": 0, "x": -0.6, "y": 0.2}, {"id": 1, "x": 0.9, "y": -0.4},
      {"id": 5, "x": 1.2, "y": 0.3}, {"id": 19, "x": 0.0, "y": 0.0}, {"id": 20, "x": 0.89, "y": 0.0},
      {"id": 21, "x": 1.4605, "y": 0.0}])";
  const CliOutcome plan =
      runOnDocument("plan", "{" + kEquipment + R"(, "level": "club", "balls": )" + balls + "}");
  ASSERT_EQ(plan.status, 0) << plan.err;
  const auto shot = nlohmann::json::parse(plan.out);
  ASSERT_TRUE(shot.contains("heading_deg") && shot.contains("speed"));
  const CliOutcome m = runOnDocument(
      "match", script(R"("balls": )" + balls + R"(, "turns": [)" + shot.dump() + "]"));
  ASSERT_EQ(m.status, 0) << m.err;
  const auto turn = nlohmann::json::parse(m.out)["turns"][0];
  EXPECT_NE(turn["foul"], "no-contact") << m.out;
  EXPECT_NE(turn["foul"], "wrong-ball-first") << m.out;

  // With the cue ball in hand the plan places it in the D.
  const CliOutcome in_hand = runOnDocument(
      "plan", "{" + kEquipment + R"(, "level": "club", "ball_in_hand": true, "balls": )" +
                  R"([{"id": 1, "x": 0.9, "y": -0.4}, {"id": 21, "x": 1.4605, "y": 0.0}]})");
  ASSERT_EQ(in_hand.status, 0) << in_hand.err;
  const auto placed = nlohmann::json::parse(in_hand.out);
  ASSERT_TRUE(placed.contains("cue"));
  const double x = placed["cue"][0], y = placed["cue"][1];
  EXPECT_LE(x, -1.7845 + 0.737 + 1e-9);
  EXPECT_LE(std::hypot(x + 1.7845 - 0.737, y), 0.292 + 1e-9);
}

}  // namespace
