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
