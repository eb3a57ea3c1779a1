// The `nineball match` contract for eight-ball and ten-ball, run through the real binary.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_runner.hpp"

namespace {

using nineball::testing::CliOutcome;
using nineball::testing::runOnDocument;

CliOutcome matchCli(const std::string& script) {
  return runOnDocument("match", script);
}

}  // namespace

TEST(MatchCliGames, EightBallTurnsCarryTheGroups) {
  const CliOutcome r = matchCli(R"({"game": "eight-ball", "seed": 3, "turns": [
      {"heading_deg": 0, "speed": 10}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["balls"].size(), 16u);
  ASSERT_EQ(doc["turns"].size(), 1u);
  const auto& groups = doc["turns"][0]["groups"];
  EXPECT_TRUE(groups["A"].is_null());  // open after the break
  EXPECT_TRUE(groups["B"].is_null());
  EXPECT_FALSE(doc["turns"][0].contains("call_breach"));
}

TEST(MatchCliGames, EightBallCalledPotSetsTheGroup) {
  // The 2 in line with the bottom-right pocket; the stripe and the 8 out of the way.
  const CliOutcome r = matchCli(R"({"game": "eight-ball",
      "balls": [{"id": 0, "x": 0.4, "y": 0.0}, {"id": 2, "x": 0.6496, "y": -0.1664},
                {"id": 8, "x": -0.9, "y": 0.3}, {"id": 12, "x": -0.9, "y": -0.3}],
      "turns": [{"heading_deg": -33.69, "speed": 2,
                 "call": {"ball": 2, "pocket": "bottom-right"}}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  const auto& t = doc["turns"][0];
  EXPECT_EQ(t["pocketed"], nlohmann::json::array({2}));
  EXPECT_EQ(t["groups"]["A"], "solids");
  EXPECT_EQ(t["groups"]["B"], "stripes");
  EXPECT_EQ(t["call"]["ball"], 2);
  EXPECT_EQ(t["call"]["pocket"], "bottom-right");
}

TEST(MatchCliGames, TenBallRacksTenAndWantsACallAfterTheBreak) {
  const CliOutcome ok = matchCli(R"({"game": "ten-ball", "turns": [
      {"heading_deg": 0, "speed": 10}]})");
  ASSERT_EQ(ok.status, 0) << ok.err;
  const auto doc = nlohmann::json::parse(ok.out);
  EXPECT_EQ(doc["balls"].size(), 11u);
  EXPECT_TRUE(doc["turns"][0].contains("call_breach"));
  EXPECT_FALSE(doc["turns"][0].contains("groups"));

  const CliOutcome refused = matchCli(R"({"game": "ten-ball", "turns": [
      {"heading_deg": 0, "speed": 10}, {"heading_deg": 0, "speed": 1}]})");
  EXPECT_EQ(refused.status, 2);
  EXPECT_TRUE(refused.out.empty());
  EXPECT_NE(refused.err.find(": turns[1]: every shot after the break in ten-ball is called"),
            std::string::npos)
      << refused.err;
}

TEST(MatchCliGames, BadGameFieldsAreRefused) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"game": "crokinole", "turns": []})", "game: unknown game \"crokinole\""},
      {R"({"game": "eight-ball", "rules": "paper", "turns": []})", "rules: the paper's rules"},
      {R"({"game": "ten-ball", "players": {"A": "ai:grandmaster"}})", "players.A: unknown player"},
      {R"({"turns": [{"heading_deg": 0, "speed": 1, "call": {"ball": 1, "pocket": "middle"}}]})",
       "turns[0].call.pocket: unknown pocket \"middle\""},
      {R"({"turns": [{"heading_deg": 0, "speed": 1, "call": {"ball": 16, "pocket": "top-left"}}]})",
       "turns[0].call.ball:"},
      {R"({"turns": [{"heading_deg": 0, "speed": 1, "call": {"pocket": "top-left"}}]})",
       "turns[0].call"},
      {R"({"turns": [{"decision": "rerack", "call": 1}]})", "turns[0]"},
  };
  for (const auto& [script, message] : cases) {
    const CliOutcome r = matchCli(script);
    EXPECT_EQ(r.status, 2) << script;
    EXPECT_TRUE(r.out.empty()) << script;
    EXPECT_NE(r.err.find(message), std::string::npos) << script << "\n" << r.err;
  }
}

TEST(MatchCliGames, NineBallResultsGainNoNewKeys) {
  const CliOutcome r = matchCli(R"({"seed": 7, "turns": [{"heading_deg": 0, "speed": 10}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto t = nlohmann::json::parse(r.out)["turns"][0];
  EXPECT_FALSE(t.contains("groups"));
  EXPECT_FALSE(t.contains("call_breach"));
  EXPECT_FALSE(t.contains("call"));
}

TEST(MatchCliGames, EightBallIllegalBreakThenRerack) {
  const CliOutcome r = matchCli(R"({"game": "eight-ball", "turns": [
      {"heading_deg": 0, "speed": 0.6}, {"decision": "rerack"},
      {"heading_deg": 0, "speed": 10}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto turns = nlohmann::json::parse(r.out)["turns"];
  ASSERT_EQ(turns.size(), 3u);
  EXPECT_EQ(turns[0]["foul"], "bad-break");
  EXPECT_EQ(turns[0]["next"], "B");
  EXPECT_EQ(turns[1]["decision"], "rerack");
  EXPECT_EQ(turns[1]["shooter"], "B");
  EXPECT_EQ(turns[2]["shooter"], "B");  // the chooser breaks the new rack
  EXPECT_TRUE(turns[1]["groups"]["A"].is_null());
}

// Ball numbers are checked against the game, as `plan` checks them (ball 16 in eight-ball
// played 89 no-contact fouls and went partial), and a decision word of another game is
// refused ("rerack" answered a push-out as a pass).
TEST(MatchCliGames, BallsAndDecisionsOfAnotherGameAreRefusedByName) {
  struct Case {
    const char* script;
    const char* message;
  };
  for (
      const Case& c : {
          Case{
              R"({"game":"eight-ball","balls":[{"id":0,"x":0.9,"y":0.265},{"id":16,"x":1.1,"y":0.465}],"players":{"A":"ai:easy","B":"ai:easy"}})",
              ": balls: eight-ball has no ball 16 (1-15)"},
          Case{
              R"({"game":"eight-ball","balls":[{"id":0,"x":0.9,"y":0.265},{"id":3,"x":1.1,"y":0.465}],"turns":[]})",
              ": balls: an eight-ball layout needs the 8"},
          Case{
              R"({"game":"ten-ball","balls":[{"id":0,"x":0.9,"y":0.265},{"id":15,"x":1.1,"y":0.465}],"turns":[]})",
              ": balls: ten-ball has no ball 15 (1-10)"},
          Case{R"({"turns":[{"heading_deg":0,"speed":10},{"decision":"rerack"}]})",
               ": turns[1].decision: expected \"shoot\" or \"pass\""},
          Case{
              R"({"game":"eight-ball","turns":[{"heading_deg":0,"speed":10},{"decision":"pass"}]})",
              ": turns[1].decision: expected \"play-on\" or \"rerack\""},
      }) {
    const CliOutcome r = matchCli(c.script);
    EXPECT_EQ(r.status, 2) << c.script;
    EXPECT_TRUE(r.out.empty()) << c.script;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
}
