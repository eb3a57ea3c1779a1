#include "common/named.hpp"
#include "games/eight_ball/eight_ball.hpp"
#include "games/nine_ball/nine_ball.hpp"
#include "games/ten_ball/ten_ball.hpp"
#include "games/three_cushion/three_cushion.hpp"
#include "nineball/games.hpp"

namespace nineball {

const std::vector<GameDef>& allGames() {
  static const std::vector<GameDef> all{
      games::nineBall(),
      games::eightBall(),
      games::tenBall(),
      games::threeCushion(),
  };
  return all;
}

const GameDef& gameDef(rules::Game game) {
  for (const GameDef& g : allGames()) {
    if (g.id == game) return g;
  }
  return defaultGame();
}

const GameDef& defaultGame() {
  return allGames().front();
}

const GameDef* gameNamed(const std::string& name) {
  const auto i = placeNamed(allGames(), name);
  return i ? &allGames()[*i] : nullptr;
}

std::vector<std::string> gameNames() {
  return namesOf(allGames());
}

std::string gamesPlayedBy(rules::RuleSet rules) {
  std::vector<std::string> names;
  for (const GameDef& g : allGames()) {
    if (g.playedBy(rules)) names.emplace_back(g.name);
  }
  return listed(names, "and");
}

std::string rulesOnlyFor(rules::RuleSet rules) {
  const char* whose = rules == rules::RuleSet::Paper ? "the paper's"
                      : rules == rules::RuleSet::Umb ? "the UMB"
                                                     : "the WPA";
  return std::string(whose) + " rules are " + gamesPlayedBy(rules) + "'s only";
}

bool GameDef::playedBy(rules::RuleSet r) const {
  for (rules::RuleSet s : rule_sets) {
    if (s == r) return true;
  }
  return false;
}

}  // namespace nineball
