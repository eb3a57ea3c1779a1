#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "io/match_json.hpp"

// A match script played to its end: the computer's turns planned, the script's turns played in
// order. The command line's `nineball match` and the Python package's match() share it.
namespace nineball::io {

/// How a played script ended.
struct MatchPlayed {
  enum class Outcome { Done, Partial, BadTurn, ComputerRefused };
  Outcome outcome = Outcome::Done;
  /// The result document (matchResultToJson plus "partial"); set unless a turn was refused.
  nlohmann::ordered_json doc;
  std::size_t turns = 0;  ///< turns played
  /// BadTurn: "turns[i]: why"; ComputerRefused: "the computer's turn i was refused: why".
  std::string why;
};

/// Plays `script` until the rack is won, a human is to play and the script has no turn left,
/// a shot stops with balls still moving (Partial), or the turn limit. The computer players plan
/// on `planner_threads` threads each; the result does not depend on how many.
MatchPlayed playMatchScript(const MatchScript& script, int planner_threads = 2);

}  // namespace nineball::io
