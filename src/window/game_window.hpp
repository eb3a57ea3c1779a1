#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/game_options.hpp"
#include "nineball/match.hpp"
#include "nineball/race.hpp"

namespace nineball::window {

/// How the first rack starts: its setup, and the turns of a script to play before the
/// window shows it.
struct GameStart {
  MatchSetup setup;
  std::vector<TurnInput> turns;
  std::string script_name;  ///< for messages about the script's turns
  Race race;                ///< the script's race (race_to 0: its turns play one rack)
  /// The script's setup as written (without "turns" and "players"): F5 saves the game with it.
  nlohmann::json script_setup;
  /// Online (--host): the match offered to the joiner, a script without turns and players.
  nlohmann::json online_match;
};

/// The match a host offers for `setup` (game, rules, seed, points): what the joiner plays.
nlohmann::json onlineMatchOf(const MatchSetup& setup);

/// Opens the game window and plays until the players quit; with --screenshot draws, saves
/// the PNG and exits. Returns the exit status: 0, 1 without a display, a font or a writable
/// screenshot, 2 for an illegal turn in the script.
int runGame(const app::GameOptions& options, const GameStart& start, std::ostream& err);

}  // namespace nineball::window
