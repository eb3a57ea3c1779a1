#include "window/game_command.hpp"

#include <istream>
#include <ostream>

#include "app/cli_checks.hpp"
#include "app/exit_codes.hpp"
#include "app/match_script_file.hpp"
#include "app/read_input.hpp"
#include "io/match_json.hpp"
#include "nineball/games.hpp"
#include "nineball/seat.hpp"
#include "window/game_window.hpp"

namespace nineball::window {

int runGameCommand(const app::GameOptions& options, std::istream& in, std::ostream& err) {
  GameStart start;
  start.setup.setGame(*rules::gameFromName(options.game));
  start.setup.rules = *rules::ruleSetFromName(options.rules);
  const GameDef& game = gameDef(start.setup.game);
  if (&game != &defaultGame()) {
    if (!game.playedBy(start.setup.rules)) {
      err << "nineball: --rules " << options.rules << " is " << gamesPlayedBy(start.setup.rules)
          << "'s only; " << options.game << " is played by the WPA rules\n";
      return app::kExitBadInput;
    }
    if (options.practice) {
      err << "nineball: --practice has no rules, so no game: leave out --game\n";
      return app::kExitBadInput;
    }
  }
  start.setup.seed = options.seed;
  if (!options.script.empty()) {
    start.script_name = app::shownPath(options.script);
    auto script = app::loadMatchScript(options.script, in, err, "nineball: ");
    if (!script) return app::kExitBadInput;
    // The window plays the script's turns for both seats; computer players are its own option.
    for (const Seat& player : script->players) {
      if (isComputer(player)) {
        err << "nineball: " << start.script_name
            << ": players: computer players are for nineball match; in the window use "
               "--opponent\n";
        return app::kExitBadInput;
      }
    }
    start.setup = script->setup;
    start.turns = std::move(script->turns);
  }
  return runGame(options, start, err);
}

}  // namespace nineball::window
