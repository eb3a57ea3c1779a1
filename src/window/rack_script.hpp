#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "window/game_session.hpp"

namespace nineball::window {

/// The rack in play (or just finished) as a `nineball match` script: its game, rules, seed and
/// every turn as played (the exact radians, the cue ball's place, the call, the push-out, the
/// decision in the game's words). `nineball match FILE` plays it again to the bit, and
/// `nineball --script FILE` shows where it ended. Nothing for practice, which has no rack.
std::optional<nlohmann::ordered_json> rackScript(const GameSession& session);

/// "nineball-rack-20261127-171500.json": the name F5 saves the rack under.
std::string rackScriptName();

}  // namespace nineball::window
