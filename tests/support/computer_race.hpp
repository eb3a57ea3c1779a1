#pragma once

// A match result's turns written back as a script's turns, and a race between two computers
// played headless with its turns as a script's: what a window session is fed to play the same
// match.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <variant>
#include <vector>

#include "io/match_json.hpp"
#include "io/match_play.hpp"

namespace nineball::test {

// The result's turns as a script's: what a person copying them would write (the exact radians
// of the computer's shots, the cue ball's place, the call, the push-out, the decision).
inline nlohmann::ordered_json scriptTurns(const nlohmann::ordered_json& doc) {
  nlohmann::ordered_json turns = nlohmann::ordered_json::array();
  for (const auto& t : doc.at("turns")) {
    if (t.contains("decision")) {
      turns.push_back({{"decision", t.at("decision")}});
      continue;
    }
    nlohmann::ordered_json turn;
    for (const char* key : {"heading_rad", "speed", "tip", "elevation_rad"})
      turn[key] = t.at("shot").at(key);
    if (t.contains("cue")) turn["cue"] = t.at("cue");
    if (t.contains("call")) turn["call"] = t.at("call");
    if (t.value("push_out", false)) turn["push_out"] = true;
    turns.push_back(turn);
  }
  return turns;
}

// The result without what only the computer's turns carry (who played, the shot as planned):
// what a replay of the same turns by hand must give again.
inline nlohmann::ordered_json judged(nlohmann::ordered_json doc) {
  for (auto& t : doc.at("turns")) {
    for (const char* key : {"player", "shot", "cue", "plan"}) t.erase(key);
  }
  return doc;
}

// The turns of a race between two computers, as a script's turns and the race's result.
struct ComputerRace {
  std::vector<TurnInput> turns;
  nlohmann::ordered_json doc;
};

inline ComputerRace computerRace(const char* game, int race_to, const char* breaks, int seed) {
  nlohmann::ordered_json script{{"game", game},
                                {"seed", seed},
                                {"race_to", race_to},
                                {"breaks", breaks},
                                {"players", {{"A", "ai:pro"}, {"B", "ai:pro"}}}};
  const io::MatchScriptResult parsed = io::parseMatchScript(script.dump());
  const io::MatchPlayed played = io::playMatchScript(std::get<io::MatchScript>(parsed));
  EXPECT_EQ(played.outcome, io::MatchPlayed::Outcome::Done) << played.why;
  script.erase("players");
  script["turns"] = scriptTurns(played.doc);
  const io::MatchScriptResult plain = io::parseMatchScript(script.dump());
  return {std::get<io::MatchScript>(plain).turns, played.doc};
}

}  // namespace nineball::test
