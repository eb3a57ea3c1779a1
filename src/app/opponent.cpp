#include "app/opponent.hpp"

#include <array>

namespace nineball::app {
namespace {

const std::array<Opponent, 4> kCycle = {std::nullopt, ai::Level::Easy, ai::Level::Medium,
                                        ai::Level::Hard};

}  // namespace

std::string opponentName(const Opponent& opponent) {
  return opponent ? std::string("ai:") + ai::levelName(*opponent) : "human";
}

std::optional<Opponent> opponentFromName(const std::string& name) {
  for (const Opponent& o : kCycle) {
    if (name == opponentName(o)) return o;
  }
  return std::nullopt;
}

std::vector<std::string> opponentNames() {
  std::vector<std::string> names;
  for (const Opponent& o : kCycle) names.push_back(opponentName(o));
  return names;
}

std::string opponentLabel(const Opponent& opponent) {
  return opponent ? std::string("vs computer (") + ai::levelName(*opponent) + ")" : "2 players";
}

Opponent nextOpponent(const Opponent& opponent) {
  for (std::size_t i = 0; i < kCycle.size(); ++i) {
    if (kCycle[i] == opponent) return kCycle[(i + 1) % kCycle.size()];
  }
  return std::nullopt;
}

}  // namespace nineball::app
