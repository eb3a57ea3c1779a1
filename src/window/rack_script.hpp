#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "window/game_session.hpp"

namespace nineball::window {

/// The game in play as a `nineball match` script: in a match of several racks (bestOf()) the
/// whole match from its first rack ("race_to", "breaks", the first rack's seed and every turn
/// of every rack), else the rack in play (or just finished). Its game, rules, seed and each turn
/// as played (the exact radians, the cue ball's place, the call, the push-out, the decision in
/// the game's words), on `setup`'s table, physics and layout (a script's own, or the game's when
/// empty). `nineball match FILE` plays it again to the bit, and `nineball --script FILE [--watch]`
/// in the window. Nothing for practice, which has no rack.
std::optional<nlohmann::ordered_json> gameScript(const GameSession& session,
                                                 const nlohmann::json& setup = {});

/// Whether gameScript() writes the whole match: a race whose every turn the session has seen,
/// not online (where the host breaks every rack, which no script says).
bool savesMatch(const GameSession& session);

/// "nineball-rack-20261127-171500.json" ("nineball-match-..." for a match): the name F5 saves
/// the game under.
std::string gameScriptName(bool match);

}  // namespace nineball::window
