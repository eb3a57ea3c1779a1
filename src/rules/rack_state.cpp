#include "nineball/rules.hpp"
#include "rules/ball_list.hpp"

namespace nineball::rules {

std::optional<PocketId> ShotSummary::pocketOf(int ball) const {
  for (std::size_t i = 0; i < pocketed.size() && i < pockets.size(); ++i) {
    if (pocketed[i] == ball) return pockets[i];
  }
  return std::nullopt;
}

bool RackState::has(int ball) const {
  return contains(on_table, ball);
}

void RackState::remove(const std::vector<int>& balls) {
  for (int b : balls) erase(on_table, b);
}

}  // namespace nineball::rules
