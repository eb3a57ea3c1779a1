#include "window/game_window.hpp"

#include <optional>

#include "window/game_loop.hpp"

namespace nineball::window {

nlohmann::json onlineMatchOf(const MatchSetup& setup) {
  nlohmann::json match = {{"game", rules::gameName(setup.game)},
                          {"rules", rules::ruleSetName(setup.rules)},
                          {"seed", setup.seed}};
  if (setup.points > 0) match["points"] = setup.points;
  return match;
}

int runGame(const app::GameOptions& options, const GameStart& start, std::ostream& err) {
  GameLoop loop(options, start, err);
  if (const std::optional<int> status = loop.setupStatus()) return *status;
  return loop.run();
}

}  // namespace nineball::window
