#include "nineball/race.hpp"

#include <cstring>

namespace nineball {

const char* breakOrderName(BreakOrder order) {
  return order == BreakOrder::Winner ? "winner" : "alternate";
}

std::optional<BreakOrder> breakOrderFromName(const char* name) {
  for (BreakOrder order : {BreakOrder::Alternate, BreakOrder::Winner}) {
    if (std::strcmp(name, breakOrderName(order)) == 0) return order;
  }
  return std::nullopt;
}

rules::Player rackOpener(BreakOrder order, int index, std::optional<rules::Player> last_winner) {
  if (index <= 0) return rules::Player::A;
  if (order == BreakOrder::Winner) return last_winner.value_or(rules::Player::A);
  return index % 2 == 0 ? rules::Player::A : rules::Player::B;
}

MatchSetup rackSetup(const MatchSetup& first, int index, rules::Player opener) {
  MatchSetup s = first;
  if (index > 0) {
    s.balls.reset();
    s.seed = first.seed + static_cast<std::uint64_t>(index);
  }
  s.opener = opener;
  return s;
}

std::optional<rules::Player> RaceScore::winner(const Race& race) const {
  if (race.race_to <= 0) return std::nullopt;
  if (won[0] >= race.race_to) return rules::Player::A;
  if (won[1] >= race.race_to) return rules::Player::B;
  return std::nullopt;
}

void RaceScore::count(std::optional<rules::Player> rack_winner) {
  if (rack_winner) ++won[*rack_winner == rules::Player::A ? 0 : 1];
}

}  // namespace nineball
