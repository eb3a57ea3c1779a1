#include "window/game_help.hpp"

#include "nineball/games.hpp"

namespace nineball::window {

std::vector<std::string> gameHelpLines(rules::Game game) {
  return gameDef(game).help;
}

std::string groupLabel(const rules::Groups& groups, rules::Player player) {
  const auto g = groups.of(player);
  return g ? rules::groupName(*g) : "open table";
}

}  // namespace nineball::window
