#pragma once

#include <array>
#include <string>

#include "nineball/games.hpp"
#include "nineball/race.hpp"
#include "nineball/rules.hpp"
#include "nineball/seat.hpp"

namespace nineball::window {

/// The games the start menu offers.
enum class GameMode {
  Match,     ///< a match, rack after rack, of the game chosen
  Practice,  ///< practice mode: no rules, any ball anywhere (GameSession's practice)
};

/// What the start menu settled: the game, who plays Player 2, the rules, the names, or the
/// saved rack to resume. No SFML; also kept in the settings as the last game chosen.
struct MenuChoice {
  GameMode mode = GameMode::Match;
  rules::Game game = defaultGame().id;  ///< the game of a match (practice: none)
  Seat opponent;  ///< who plays Player 2: a second person, or the computer at a level
  rules::RuleSet rules = rules::RuleSet::Wpa;
  /// The distance of a game played to points (GameTexts::points_choices; 0: the game's default).
  int points = 0;
  /// A match of frames or racks: best of N, a race to ceil(N/2) (GameTexts::best_of_choices; 0:
  /// none, the racks add up).
  int best_of = 0;
  /// Who breaks the racks of a match after its first.
  BreakOrder breaks = BreakOrder::Alternate;
  std::array<std::string, 2> names = {"Player 1", "Player 2"};
  bool resume = false;  ///< play on the saved rack instead (the rest is then the saved one's)
};

/// The frames that win a match of best of `best_of`: ceil(N/2); 0 for no match length.
constexpr int framesToWinMatch(int best_of) {
  return (best_of + 1) / 2;
}

}  // namespace nineball::window
