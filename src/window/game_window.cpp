#include "window/game_window.hpp"

#include <optional>

#include "window/game_loop.hpp"

namespace nineball::window {

int runGame(const app::GameOptions& options, const GameStart& start, std::ostream& err) {
  GameLoop loop(options, start, err);
  if (const std::optional<int> status = loop.setupStatus()) return *status;
  return loop.run();
}

}  // namespace nineball::window
