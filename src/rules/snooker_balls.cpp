#include "rules/snooker_balls.hpp"

#include <algorithm>

namespace nineball::rules::snooker {
namespace {

// A red potted is followed by a colour: at most the black's 7 (WPBSA 3.5: the maximum).
constexpr int kRedAndBlack = 8;

// "the blue": a colour as players name it.
std::string colourName(int ball) {
  static const char* const kNames[] = {"yellow", "green", "brown", "blue", "pink", "black"};
  return isColour(ball) ? std::string("the ") + kNames[ball - kYellow]
                        : "ball " + std::to_string(ball);
}

constexpr const char* kNoFreeBall =
    "no free ball is due (one follows only a foul that leaves the striker snookered)";

}  // namespace

std::optional<std::string> nominationProblem(const RackState& s, int ball) {
  if (s.snooker.free_ball) return std::nullopt;  // any ball may be nominated (WPBSA 3.12)
  if (isRed(ball)) {
    return std::string(
               "a red is never nominated: after a red the striker nominates a colour, and ") +
           kNoFreeBall;
  }
  if (s.snooker.colour_on) return std::nullopt;
  const std::vector<int> on = ballsOn(s);
  if (redsRemain(s)) {
    return colourName(ball) +
           " cannot be nominated: a red is on (a colour is nominated after a red is potted), and " +
           kNoFreeBall;
  }
  if (!on.empty() && on.front() != ball) {
    return colourName(ball) + " cannot be nominated: the colours are taken in order and " +
           colourName(on.front()) + " is on, and " + kNoFreeBall;
  }
  return std::nullopt;
}

bool redsRemain(const RackState& s) {
  return std::any_of(s.on_table.begin(), s.on_table.end(), isRed);
}

std::vector<int> ballsOn(const RackState& s) {
  std::vector<int> on;
  if (s.snooker.respotted_black) {
    if (s.has(kBlack)) on.push_back(kBlack);
    return on;
  }
  const bool reds = redsRemain(s);
  for (int b : s.on_table) {
    if (s.snooker.colour_on ? isColour(b) : reds ? isRed(b) : isColour(b)) on.push_back(b);
  }
  // Colours in ascending order once the reds and the colour after the last one are gone.
  if (!s.snooker.colour_on && !reds && on.size() > 1) on.resize(1);
  return on;
}

int pointsRemaining(const RackState& s) {
  int reds = 0;
  int colours = 0;
  for (int b : s.on_table) {
    if (isRed(b)) ++reds;
    if (isColour(b)) colours += value(b);
  }
  if (s.snooker.respotted_black) return colours;
  return reds * kRedAndBlack + colours + (s.snooker.colour_on ? value(kBlack) : 0);
}

bool snookersRequired(const RackState& s, Player p) {
  const int me = s.score[p == Player::A ? 0 : 1];
  const int them = s.score[p == Player::A ? 1 : 0];
  return them - me > pointsRemaining(s);
}

}  // namespace nineball::rules::snooker
