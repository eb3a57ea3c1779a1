#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/rules.hpp"

// The "game" and "rules" fields that `match` and `plan` documents share.
namespace nineball::io {

/// The document's optional "game" (nine-ball when absent).
rules::Game gameField(const nlohmann::json& doc);

/// The document's optional "rules" (WPA when absent); the paper's rules are refused outside
/// nine-ball.
rules::RuleSet rulesField(const nlohmann::json& doc, rules::Game game);

/// The object balls a layout of `game` may hold: at least one; in eight-ball 1-15 and the 8
/// among them (the rack is won on it), in ten-ball 1-10. Nine-ball takes any ids (scenes do).
/// Refuses "balls" naming the ball.
void checkGameBalls(rules::Game game, const std::vector<BallState>& balls);

/// The decision words of `game`: "play-on" / "rerack" answer an illegal eight-ball break,
/// "shoot" / "pass" a nine- or ten-ball push-out (or a ten-ball pot not as called). True for
/// play on / shoot. Refuses `path` for another game's word or an unknown one.
bool decisionField(const std::string& word, rules::Game game, const std::string& path);

}  // namespace nineball::io
