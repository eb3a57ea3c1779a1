#pragma once

#include <string>
#include <vector>

#include "nineball/games.hpp"

namespace nineball {

/// What a game shows people rather than what it is, kept out of the public GameDef: the help
/// screen's lines on its rules, the window menu's choices and ai-bench's words.
struct GameTexts {
  /// The help screen's lines on its rules.
  std::vector<std::string> help;
  /// The menu's distances for a game played to points (GameDef::default_points the default);
  /// none for a game won on a ball.
  std::vector<int> points_choices;
  /// The window's match lengths, best of N (the first to win ceil(N/2) frames or racks wins
  /// the match), the first the default: snooker's frames, pool's race to N racks (0 among
  /// them: no limit, the racks simply follow one another); none for a game without matches.
  std::vector<int> best_of_choices;
  /// What `ai-bench` counts as a position made.
  const char* made = "potted the ball on";
};

/// The texts of `game`.
const GameTexts& gameTexts(rules::Game game);

namespace games {

/// One game of the registry as its folder makes it: its definition and its texts.
struct GameEntry {
  GameDef def;
  GameTexts texts;
};

}  // namespace games
}  // namespace nineball
