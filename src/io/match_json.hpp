#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <variant>
#include <vector>

#include "io/parse_error.hpp"
#include "nineball/match.hpp"
#include "nineball/planner.hpp"
#include "nineball/race.hpp"
#include "nineball/seat.hpp"

namespace nineball::io {

/// A match script: how the rack starts, who plays, and the turns of the human players.
struct MatchScript {
  MatchSetup setup;  ///< the first rack's
  Race race;         ///< race_to 0: the script plays one rack
  std::array<Seat, 2> players{};  ///< A, B; both human unless "players" says otherwise
  std::vector<TurnInput> turns;
};

/// A turn the computer played, as the result shows it.
struct ComputerTurn {
  ai::Level level = ai::Level::Master;
  TurnInput input;  ///< the shot as executed (noise included), or the decision
};

using MatchScriptResult = std::variant<MatchScript, ParseError>;

/// Parses `{"game", "rules", "seed", "table", "physics", "step", "balls", "players", "turns",
/// "points", "race_to", "breaks"}`;
/// a turn may carry "call": {"ball", "pocket"};
/// refusals name the field ("turns[2].speed: ...", "players.A: ..."). "turns" may be left out
/// when a player is the computer.
MatchScriptResult parseMatchScript(std::string_view text);

/// One turn of a script at `path` ({"heading_deg", "speed", ..., "cue", "call", "push_out"} or
/// {"decision": word}), checked as `nineball match` checks it; throws ParseError.
TurnInput parseTurn(const nlohmann::json& v, const std::string& path, double cue_mass,
                    rules::Game game);
/// The turn as a script writes it, which parseTurn reads back. Angles go over in degrees, so
/// the turn read back may differ from `turn` in the last bit: play the one read back.
nlohmann::ordered_json turnToJson(const TurnInput& turn, rules::Game game);

/// The result document: {"turns": [...], "winner": null|"A"|"B", "balls": [...]}. A turn the
/// computer played (`computer[i]` set) also carries "player": "ai:<level>" and, for a shot,
/// "shot": {"heading_deg", "speed", "tip"} and "cue" when it placed the cue ball. A called
/// shot echoes its "call"; games whose pot not as called passes the turn carry "call_breach" (null,
/// "wrong-pocket" or "no-call"), games of groups "groups": {"A", "B"} ("solids", "stripes" or
/// null).
nlohmann::ordered_json matchResultToJson(
    const std::vector<TurnRecord>& turns, const rules::Rack& rack,
    const std::vector<BallState>& balls,
    const std::vector<std::optional<ComputerTurn>>& computer = {});

}  // namespace nineball::io
