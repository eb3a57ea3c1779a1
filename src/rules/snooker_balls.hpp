#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nineball/rules.hpp"

// Snooker's balls and what they are worth (the shared contract of issue 34): the cue ball 0,
// reds 1-15 (1 point each), yellow 16 (2), green 17 (3), brown 18 (4), blue 19 (5), pink 20
// (6), black 21 (7): a colour is worth its id - 14.
namespace nineball::rules::snooker {

inline constexpr int kFirstRed = 1;
inline constexpr int kLastRed = 15;
inline constexpr int kYellow = 16;
inline constexpr int kGreen = 17;
inline constexpr int kBrown = 18;
inline constexpr int kBlue = 19;
inline constexpr int kPink = 20;
inline constexpr int kBlack = 21;

inline bool isRed(int ball) {
  return ball >= kFirstRed && ball <= kLastRed;
}
inline bool isColour(int ball) {
  return ball >= kYellow && ball <= kBlack;
}
/// Points a ball is worth when potted as the ball on (0 for the cue ball or another id).
inline int value(int ball) {
  if (isRed(ball)) return 1;
  return isColour(ball) ? ball - 14 : 0;
}

/// Why `ball` cannot be nominated for the coming stroke (a colour after a red, any ball as a
/// free ball; never a red otherwise, nor a colour while a red or a lower colour is on), in
/// words that name the ball; nothing when it may.
std::optional<std::string> nominationProblem(const RackState& s, int ball);

/// Any red on the table.
bool redsRemain(const RackState& s);
/// The balls on for the coming stroke without a free ball: every red while reds remain and no
/// red was just potted; every colour after a red; else the lowest colour left (the black alone
/// in a re-spotted black game).
std::vector<int> ballsOn(const RackState& s);
/// The most points the balls left can still give (WPBSA's "points remaining"): 8 for a red
/// and its colour (the black), the colours' 27, 7 more while a colour is on after a red.
int pointsRemaining(const RackState& s);
/// The deficit of `p` to the other is more than the points remaining: he needs snookers.
bool snookersRequired(const RackState& s, Player p);

}  // namespace nineball::rules::snooker
