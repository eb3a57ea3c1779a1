// The `nineball match` contract, run through the real binary.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_runner.hpp"

namespace {

struct CliRun {
  int status = -1;
  std::string out;
};

CliRun runMatch(const std::string& script) {
  const auto r = nineball::testing::runOnDocument("match", script);
  return {r.status, r.out};
}

}  // namespace

TEST(MatchCli, PlaysAScriptAndPrintsEveryTurn) {
  const CliRun r = runMatch(R"({"rules": "wpa", "seed": 7, "turns": [
      {"heading_deg": 0, "speed": 10},
      {"push_out": true, "heading_deg": 90, "speed": 0.4},
      {"decision": "pass"}]})");
  ASSERT_EQ(r.status, 0);
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["turns"].size(), 3u);
  for (const auto& t : doc["turns"]) {
    for (const char* key :
         {"shooter", "result", "foul", "pocketed", "next", "ball_on", "ball_in_hand", "winner"}) {
      EXPECT_TRUE(t.contains(key)) << key;
    }
  }
  EXPECT_EQ(doc["turns"][0]["shooter"], "A");
  EXPECT_EQ(doc["turns"][2]["decision"], "pass");
  EXPECT_TRUE(doc["winner"].is_null());
  EXPECT_EQ(doc["balls"].size(), 10u);
}

TEST(MatchCli, IllegalActionsStopWithStatusTwoAndNothingOnStdout) {
  const char* scripts[] = {
      // a push-out on the break
      R"({"turns": [{"push_out": true, "heading_deg": 0, "speed": 10}]})",
      // the cue ball placed on the table's far side for the break
      R"({"turns": [{"heading_deg": 0, "speed": 10, "cue": [0.5, 0.0]}]})",
      // the cue ball placed off the table
      R"({"turns": [{"heading_deg": 0, "speed": 10, "cue": [-3.0, 0.0]}]})",
      // a decision with no push-out
      R"({"turns": [{"decision": "shoot"}]})",
      // a shot after the game ended: the 1 and the 9 in line with the bottom-right pocket
      R"({"balls": [{"id": 0, "x": 0.2, "y": 0.1}, {"id": 9, "x": 0.5, "y": -0.1}],
          "turns": [{"heading_deg": -33.69, "speed": 3},
                    {"heading_deg": 0, "speed": 1}]})",
      // not a script
      R"({"turns": [{"heading_deg": 0}]})",
      R"([1, 2])",
  };
  for (const char* s : scripts) {
    const CliRun r = runMatch(s);
    EXPECT_EQ(r.status, 2) << s;
    EXPECT_TRUE(r.out.empty()) << s;
  }
}
