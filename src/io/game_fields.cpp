#include "io/game_fields.hpp"

#include <string>

#include "io/json_fields.hpp"

namespace nineball::io {

rules::Game gameField(const nlohmann::json& doc) {
  const nlohmann::json* p = optional(doc, "game");
  if (!p) return rules::Game::NineBall;
  const std::string name = text(*p, "game");
  const auto game = rules::gameFromName(name);
  if (!game) {
    refuse("game", "unknown game " + quote(name) +
                       " (expected \"nine-ball\", \"eight-ball\" or \"ten-ball\")");
  }
  return *game;
}

rules::RuleSet rulesField(const nlohmann::json& doc, rules::Game game) {
  const nlohmann::json* p = optional(doc, "rules");
  if (!p) return rules::RuleSet::Wpa;
  const std::string name = text(*p, "rules");
  const auto found = rules::ruleSetFromName(name);
  if (!found) refuse("rules", "unknown rules " + quote(name) + " (expected \"wpa\" or \"paper\")");
  if (*found == rules::RuleSet::Paper && game != rules::Game::NineBall) {
    refuse("rules", std::string("the paper's rules are nine-ball's only, not ") +
                        rules::gameName(game) + "'s");
  }
  return *found;
}

}  // namespace nineball::io
