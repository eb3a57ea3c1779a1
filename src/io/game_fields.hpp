#pragma once

#include <nlohmann/json.hpp>

#include "nineball/rules.hpp"

// The "game" and "rules" fields that `match` and `plan` documents share.
namespace nineball::io {

/// The document's optional "game" (nine-ball when absent).
rules::Game gameField(const nlohmann::json& doc);

/// The document's optional "rules" (WPA when absent); the paper's rules are refused outside
/// nine-ball.
rules::RuleSet rulesField(const nlohmann::json& doc, rules::Game game);

}  // namespace nineball::io
