#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/rules.hpp"

// The "game" and "rules" fields that `match` and `plan` documents share.
namespace nineball::io {

/// The document's optional "game" (the registry's default game when absent).
rules::Game gameField(const nlohmann::json& doc);

/// The document's optional "rules" (WPA when absent); rules the game is not played by
/// (GameDef::rule_sets) are refused.
rules::RuleSet rulesField(const nlohmann::json& doc, rules::Game game);

/// The object balls a layout of `game` may hold: at least one; within the game's highest
/// number (GameDef::highest_ball) and holding its required balls (GameDef::required_balls).
/// Refuses "balls" naming the ball.
void checkGameBalls(rules::Game game, const std::vector<BallState>& balls);

/// The decision words of `game`: GameDef::decision ("shoot" / "pass" after a push-out,
/// "play-on" / "rerack" after an illegal break). True for
/// play on / shoot. Refuses `path` for another game's word or an unknown one.
bool decisionField(const std::string& word, rules::Game game, const std::string& path);

}  // namespace nineball::io
