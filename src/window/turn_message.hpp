#pragma once

#include <string>

#include "nineball/match.hpp"
#include "nineball/rules.hpp"
#include "render/hud_state.hpp"

namespace nineball::window {

/// A line for the players about a finished turn, and how it reads.
struct TurnMessage {
  std::string text;
  render::Tone tone = render::Tone::Info;
};

/// Says what a turn gave: what dropped, the foul and its reason, ball in hand, the push-out
/// choice, the winner. `ball_on` is the ball on before the shot; `shooter` names the player
/// who played the turn and `opponent` the other one (the record says which of them plays
/// next); `groups_before` the groups before the shot (the message says when they are settled).
TurnMessage describeTurn(const TurnRecord& record, const rules::ShotSummary& summary, int ball_on,
                         const std::string& shooter, const std::string& opponent,
                         const rules::Groups& groups_before = {});

/// What a carom turn gave, for the players: the point and its cushions, or why there was none,
/// who plays next, or the game's end with the score.
TurnMessage describeCaromTurn(const TurnRecord& record, const rules::Rack& rack,
                              const std::string& shooter, const std::string& opponent);

/// `text` as the start of a sentence: its first letter a capital ("the 9" -> "The 9").
std::string sentence(std::string text);

/// "the 3", "the 3 and the 5", "the 2, the 3 and the 7".
std::string ballList(const std::vector<int>& balls);

}  // namespace nineball::window
