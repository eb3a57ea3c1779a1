// `nineball match` with computer players, run through the real binary.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_runner.hpp"

using nineball::testing::CliOutcome;
using nineball::testing::runOnDocument;

TEST(MatchAiCli, TwoComputerPlayersPlayARackToItsEndTheSameWayEveryTime) {
  const std::string script = R"({"seed": 3, "players": {"A": "ai:easy", "B": "ai:easy"}})";
  const CliOutcome first = runOnDocument("match", script);
  ASSERT_EQ(first.status, 0) << first.err;
  const auto doc = nlohmann::json::parse(first.out);
  EXPECT_FALSE(doc["winner"].is_null());
  ASSERT_FALSE(doc["turns"].empty());
  for (const auto& t : doc["turns"]) {
    EXPECT_EQ(t["player"], "ai:casual");  // "easy" is the older name of casual
    if (!t.contains("decision")) {
      EXPECT_TRUE(t.contains("shot"));
    }
  }
  EXPECT_EQ(doc["turns"][0]["cue"].size(), 2u);  // the break places the cue ball
  const CliOutcome second = runOnDocument("match", script);
  EXPECT_EQ(second.out, first.out);
}

TEST(MatchAiCli, TwoComputersPlayEightBallAndTenBallRacksToTheirEnd) {
  for (const char* game : {"eight-ball", "ten-ball"}) {
    const std::string script = std::string(R"({"game": ")") + game +
                               R"(", "seed": 4, "players": {"A": "ai:easy", "B": "ai:easy"}})";
    const CliOutcome first = runOnDocument("match", script);
    ASSERT_EQ(first.status, 0) << game << ": " << first.err;
    const auto doc = nlohmann::json::parse(first.out);
    EXPECT_FALSE(doc["winner"].is_null()) << game;
    bool called = false;
    for (const auto& t : doc["turns"]) {
      called = called || t.contains("call");
      if (std::string(game) == "eight-ball") {
        EXPECT_TRUE(t.contains("groups"));
      }
    }
    // Ten-ball calls every shot after the break; eight-ball calls the 8, which a won rack
    // was either potted on (called) or lost on.
    if (std::string(game) == "ten-ball") {
      EXPECT_TRUE(called);
    }
    const CliOutcome second = runOnDocument("match", script);
    EXPECT_EQ(second.out, first.out) << game;
  }
}

TEST(MatchAiCli, AHumanPlaysFromTheScriptUntilItRunsOut) {
  // A breaks from the script; B is the computer; the rack stops when A has no turn left.
  const CliOutcome r = runOnDocument("match", R"({"seed": 2,
      "players": {"A": "human", "B": "ai:easy"},
      "turns": [{"heading_deg": 0, "speed": 0.5}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_GE(doc["turns"].size(), 2u);
  EXPECT_FALSE(doc["turns"][0].contains("player"));
  EXPECT_EQ(doc["turns"][1]["player"], "ai:casual");
  if (doc["winner"].is_null()) {
    EXPECT_EQ(doc["turns"].back()["next"], "A");
  }
}

TEST(MatchAiCli, RefusesAnUnknownPlayer) {
  for (const char* script :
       {R"({"players": {"A": "ai:godlike"}})", R"({"players": {"A": "human", "C": "ai:easy"}})",
        R"({"players": ["ai:easy"]})", R"({"players": {"B": 1}})"}) {
    const CliOutcome r = runOnDocument("match", script);
    EXPECT_EQ(r.status, 2) << script;
    EXPECT_TRUE(r.out.empty()) << script;
    EXPECT_NE(r.err.find("players"), std::string::npos) << r.err;
  }
  const CliOutcome r = runOnDocument("match", R"({"players": {"A": "ai:godlike"}})");
  EXPECT_NE(r.err.find("players.A: unknown player"), std::string::npos) << r.err;
}

TEST(MatchAiCli, HumansStillNeedTurns) {
  const CliOutcome r = runOnDocument("match", R"({"players": {"A": "human", "B": "human"}})");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("turns"), std::string::npos) << r.err;
}

// A whole three-cushion game between two computers, pinned turn by turn (who shot, whether it
// scored, the cushions before the second ball) with the final score: the game, its rules and
// both planners must play it the same way on every build.
TEST(MatchAiCli, GoldenThreeCushionGameBetweenTwoComputers) {
  const std::string script = R"({"game": "three-cushion", "seed": 3, "points": 4,
      "players": {"A": "ai:advanced", "B": "ai:pro"}})";
  const CliOutcome first = runOnDocument("match", script);
  ASSERT_EQ(first.status, 0) << first.err;
  const auto doc = nlohmann::json::parse(first.out);
  struct Turn {
    const char* shooter;
    bool point;
    int cushions;
  };
  // A reaches the distance in its second inning; B's last inning (equal innings) misses.
  const Turn expected[] = {{"A", false, 2}, {"B", true, 4}, {"B", false, 4}, {"A", true, 5},
                           {"A", true, 3},  {"A", true, 3}, {"A", true, 4},  {"B", false, 5}};
  ASSERT_EQ(doc["turns"].size(), std::size(expected)) << first.out;
  for (std::size_t i = 0; i < std::size(expected); ++i) {
    const auto& t = doc["turns"][i];
    EXPECT_EQ(t["shooter"], expected[i].shooter) << "turn " << i;
    EXPECT_EQ(t["point"], expected[i].point) << "turn " << i;
    EXPECT_EQ(t["cushions"], expected[i].cushions) << "turn " << i;
    EXPECT_TRUE(t.contains("score") && t.contains("shot")) << "turn " << i;
  }
  EXPECT_EQ(doc["winner"], "A");
  EXPECT_EQ(doc["draw"], false);
  EXPECT_EQ(doc["points"], 4);
  const nlohmann::json a = {
      {"points", 4}, {"innings", 2}, {"run", 0}, {"average", 2.0}, {"high_run", 4}};
  const nlohmann::json b = {
      {"points", 1}, {"innings", 2}, {"run", 0}, {"average", 0.5}, {"high_run", 1}};
  EXPECT_EQ(doc["score"]["A"], a);
  EXPECT_EQ(doc["score"]["B"], b);
  EXPECT_EQ(runOnDocument("match", script).out, first.out);
}

TEST(MatchAiCli, AThreeCushionScriptIsRefusedPointsItCannotPlay) {
  for (const char* points : {"0", "101", "2.5", "\"25\""}) {
    const CliOutcome r = runOnDocument(
        "match", std::string(R"({"game": "three-cushion", "points": )") + points + "}");
    EXPECT_EQ(r.status, 2) << points;
    EXPECT_NE(r.err.find("points"), std::string::npos) << r.err;
  }
  const CliOutcome pool = runOnDocument("match", R"({"points": 9, "turns": []})");
  EXPECT_EQ(pool.status, 2);
  EXPECT_NE(pool.err.find("nine-ball is won on a ball"), std::string::npos) << pool.err;
}
