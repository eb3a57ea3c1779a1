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

void checkGameBalls(rules::Game game, const std::vector<BallState>& balls) {
  bool object_ball = false, eight = false;
  for (const BallState& b : balls) {
    if (b.id == kCueBall) continue;
    object_ball = true;
    eight = eight || b.id == 8;
    const int last = game == rules::Game::EightBall ? 15 : game == rules::Game::TenBall ? 10 : 0;
    if (last > 0 && b.id > last) {
      refuse("balls", std::string(rules::gameName(game)) + " has no ball " + std::to_string(b.id) +
                          " (1-" + std::to_string(last) + ")");
    }
  }
  if (!object_ball) refuse("balls", "no object ball to play (ids other than 0)");
  if (game == rules::Game::EightBall && !eight) {
    refuse("balls", "an eight-ball layout needs the 8 (the rack is won on it)");
  }
}

bool decisionField(const std::string& word, rules::Game game, const std::string& path) {
  const bool eight_ball = game == rules::Game::EightBall;
  const char* const expected = eight_ball ? "\"play-on\" or \"rerack\" (eight-ball's choice after "
                                            "an illegal break)"
                                          : "\"shoot\" or \"pass\" (the choice after a push-out)";
  if (eight_ball && (word == "play-on" || word == "rerack")) return word == "play-on";
  if (!eight_ball && (word == "shoot" || word == "pass")) return word == "shoot";
  refuse(path, std::string("expected ") + expected + " in " + rules::gameName(game) + ", found " +
                   quote(word));
}

}  // namespace nineball::io
