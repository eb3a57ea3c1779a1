#pragma once

// A race between two computers, played headless, and its turns as a script's: what a window
// session is fed to play the same match.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <variant>
#include <vector>

#include "io/match_json.hpp"
#include "io/match_play.hpp"

namespace nineball::test {

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
  nlohmann::ordered_json turns = nlohmann::ordered_json::array();
  for (const auto& t : played.doc.at("turns")) {
    nlohmann::ordered_json turn;
    if (t.contains("decision")) {
      turns.push_back({{"decision", t.at("decision")}});
      continue;
    }
    for (const char* key : {"heading_rad", "speed", "tip", "elevation_rad"})
      turn[key] = t.at("shot").at(key);
    if (t.contains("cue")) turn["cue"] = t.at("cue");
    if (t.contains("call")) turn["call"] = t.at("call");
    if (t.value("push_out", false)) turn["push_out"] = true;
    turns.push_back(turn);
  }
  script.erase("players");
  script["turns"] = turns;
  const io::MatchScriptResult plain = io::parseMatchScript(script.dump());
  return {std::get<io::MatchScript>(plain).turns, played.doc};
}

}  // namespace nineball::test
