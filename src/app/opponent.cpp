#include "app/opponent.hpp"

#include <vector>

namespace nineball::app {
namespace {

// Two players, then the computer at each level, the weakest first.
std::vector<Seat> cycle() {
  std::vector<Seat> seats = {HumanSeat{}};
  for (ai::Level l : ai::allLevels()) seats.emplace_back(ComputerSeat{l});
  return seats;
}

}  // namespace

std::vector<std::string> opponentNames() {
  std::vector<std::string> names;
  for (const Seat& o : cycle()) names.push_back(seatName(o));
  return names;
}

std::string opponentLabel(const Seat& opponent) {
  const auto level = computerLevel(opponent);
  return level ? std::string("vs computer (") + ai::levelName(*level) + ")" : "2 players";
}

Seat nextOpponent(const Seat& opponent) {
  const std::vector<Seat> seats = cycle();
  for (std::size_t i = 0; i < seats.size(); ++i) {
    if (seats[i] == opponent) return seats[(i + 1) % seats.size()];
  }
  return HumanSeat{};
}

}  // namespace nineball::app
