#include "window/game_help.hpp"

namespace nineball::window {

std::vector<std::string> gameHelpLines(rules::Game game) {
  switch (game) {
    case rules::Game::EightBall:
      return {"Eight-ball: the first legal pot takes its group (solids 1-7 or stripes 9-15);",
              "  hit your own group first, clear it, then call the 8 to win (8 early loses)",
              "Calling: click a pocket, or K for the obvious shot; the call shows on the table"};
    case rules::Game::TenBall:
      return {"Ten-ball: hit the lowest ball first; every shot after the break is called,",
              "  a pot not as called ends the turn (play or pass); the 10 called wins",
              "Calling: click a ball (default: the ball on), then a pocket; K: the obvious shot"};
    case rules::Game::NineBall:
      break;
  }
  return {"Rules: hit the lowest ball first; the 9 wins the rack"};
}

std::string groupLabel(const rules::Groups& groups, rules::Player player) {
  const auto g = groups.of(player);
  return g ? rules::groupName(*g) : "open table";
}

}  // namespace nineball::window
