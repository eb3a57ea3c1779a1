#pragma once

#include <nlohmann/json.hpp>
#include <string_view>
#include <variant>
#include <vector>

#include "io/parse_error.hpp"
#include "nineball/match.hpp"

namespace nineball::io {

/// A match script: how the rack starts and the turns to play.
struct MatchScript {
  MatchSetup setup;
  std::vector<TurnInput> turns;
};

using MatchScriptResult = std::variant<MatchScript, ParseError>;

/// Parses `{"rules", "seed", "table", "physics", "step", "balls", "turns"}`; refusals name
/// the field ("turns[2].speed: ...").
MatchScriptResult parseMatchScript(std::string_view text);

/// The result document: {"turns": [...], "winner": null|"A"|"B", "balls": [...]}.
nlohmann::ordered_json matchResultToJson(const std::vector<TurnRecord>& turns,
                                         const rules::Rack& rack,
                                         const std::vector<BallState>& balls);

}  // namespace nineball::io
