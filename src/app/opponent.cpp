#include "app/opponent.hpp"

#include <array>

namespace nineball::app {
namespace {

const std::array<Seat, 4> kCycle = {HumanSeat{}, ComputerSeat{ai::Level::Easy},
                                    ComputerSeat{ai::Level::Medium}, ComputerSeat{ai::Level::Hard}};

}  // namespace

std::vector<std::string> opponentNames() {
  std::vector<std::string> names;
  for (const Seat& o : kCycle) names.push_back(seatName(o));
  return names;
}

std::string opponentLabel(const Seat& opponent) {
  const auto level = computerLevel(opponent);
  return level ? std::string("vs computer (") + ai::levelName(*level) + ")" : "2 players";
}

Seat nextOpponent(const Seat& opponent) {
  for (std::size_t i = 0; i < kCycle.size(); ++i) {
    if (kCycle[i] == opponent) return kCycle[(i + 1) % kCycle.size()];
  }
  return HumanSeat{};
}

}  // namespace nineball::app
