#include "window/game_command.hpp"

#include <istream>
#include <ostream>

#include "app/cli_checks.hpp"
#include "app/exit_codes.hpp"
#include "app/match_script_file.hpp"
#include "app/read_input.hpp"
#include "io/json_reader.hpp"
#include "io/match_json.hpp"
#include "net/handshake.hpp"
#include "nineball/games.hpp"
#include "nineball/seat.hpp"
#include "window/game_window.hpp"
#include "window/rack_seed.hpp"

namespace nineball::window {

int runGameCommand(const app::GameOptions& options, std::istream& in, std::ostream& err) {
  GameStart start;
  start.setup.setGame(*rules::gameFromName(options.game));
  const GameDef& game = gameDef(start.setup.game);
  // Without --rules a game is played by its own (the first it is played by).
  if (options.rules_given) start.setup.rules = *rules::ruleSetFromName(options.rules);
  if (!game.playedBy(start.setup.rules)) {
    err << "nineball: --rules " << options.rules << " is " << gamesPlayedBy(start.setup.rules)
        << "'s only; " << options.game << " is played by the "
        << rules::ruleSetName(game.rule_sets.front()) << " rules\n";
    return app::kExitBadInput;
  }
  start.setup.seed = drawsFreshSeeds(options) ? freshSeed() : options.seed;
  const bool online = options.host_port || !options.join.empty();
  if (online && (options.practice || options.replay)) {
    err << "nineball: " << (options.practice ? "--practice" : "--replay")
        << " is for a game at this computer, not with --host or --join\n";
    return app::kExitBadInput;
  }
  if (online && options.opponent_given && options.opponent != "human") {
    err << "nineball: --opponent: online, the other seat is your friend's, not the computer's\n";
    return app::kExitBadInput;
  }
  if (!options.script.empty()) {
    start.script_name = app::shownPath(options.script);
    std::string text;
    auto script = app::loadMatchScript(options.script, in, err, "nineball: ", &text);
    if (!script) return app::kExitBadInput;
    // The window plays the script's turns for both seats (online, its own seat's);
    // computer players are its own option.
    for (const Seat& player : script->players) {
      if (isComputer(player)) {
        err << "nineball: " << start.script_name
            << ": players: computer players are for nineball match; in the window use "
               "--opponent\n";
        return app::kExitBadInput;
      }
    }
    start.setup = script->setup;
    start.race = script->race;
    start.turns = std::move(script->turns);
    // Parsed once already: the text is JSON.
    start.script_setup = net::matchPart(io::readJson(text));
    // The host offers the script's own setup (its table, physics, layout); the race is the
    // welcome's.
    if (options.host_port) {
      start.online_match = start.script_setup;
      start.online_match.erase("race_to");
      start.online_match.erase("breaks");
    }
  }
  if (start.online_match.is_null()) start.online_match = onlineMatchOf(start.setup);
  return runGame(options, start, err);
}

}  // namespace nineball::window
