#include "io/game_fields.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "io/json_fields.hpp"
#include "nineball/games.hpp"

namespace nineball::io {

rules::Game gameField(const nlohmann::json& doc) {
  const nlohmann::json* p = optional(doc, "game");
  if (!p) return defaultGame().id;
  const std::string name = text(*p, "game");
  const GameDef* game = gameNamed(name);
  if (!game) {
    std::string expected;
    const std::vector<std::string> names = gameNames();
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (i > 0) expected += i + 1 == names.size() ? " or " : ", ";
      expected += quote(names[i]);
    }
    refuse("game", "unknown game " + quote(name) + " (expected " + expected + ")");
  }
  return game->id;
}

rules::RuleSet rulesField(const nlohmann::json& doc, rules::Game game) {
  const nlohmann::json* p = optional(doc, "rules");
  if (!p) return gameDef(game).rule_sets.front();
  const std::string name = text(*p, "rules");
  const auto found = rules::ruleSetFromName(name);
  if (!found) refuse("rules", "unknown rules " + quote(name) + " (expected \"wpa\" or \"paper\")");
  if (!gameDef(game).playedBy(*found)) {
    refuse("rules", rulesOnlyFor(*found) + ", not " + gameDef(game).name + "'s");
  }
  return *found;
}

void checkGameBalls(rules::Game game, const std::vector<BallState>& balls) {
  const GameDef& def = gameDef(game);
  bool object_ball = false;
  std::vector<int> missing = def.required_balls;
  for (const BallState& b : balls) {
    if (b.id == kCueBall) continue;
    object_ball = true;
    missing.erase(std::remove(missing.begin(), missing.end(), b.id), missing.end());
    if (def.highest_ball > 0 && b.id > def.highest_ball) {
      refuse("balls", std::string(def.name) + " has no ball " + std::to_string(b.id) + " (1-" +
                          std::to_string(def.highest_ball) + ")");
    }
  }
  if (!object_ball) refuse("balls", "no object ball to play (ids other than 0)");
  if (!missing.empty()) refuse("balls", def.required_why);
}

bool decisionField(const std::string& word, rules::Game game, const std::string& path) {
  const GameDef& def = gameDef(game);
  if (word == def.decision.yes || word == def.decision.no) return word == def.decision.yes;
  refuse(path, std::string("expected ") + quote(def.decision.yes) + " or " +
                   quote(def.decision.no) + " (" + def.decision.about + ") in " + def.name +
                   ", found " + quote(word));
}

}  // namespace nineball::io
