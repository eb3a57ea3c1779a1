#include "nineball/seat.hpp"

#include "common/overloaded.hpp"

namespace nineball {
namespace {

constexpr const char* kComputerPrefix = "ai:";

}  // namespace

bool isComputer(const Seat& seat) {
  return computerLevel(seat).has_value();
}

std::optional<ai::Level> computerLevel(const Seat& seat) {
  return std::visit(
      Overloaded{[](const HumanSeat&) -> std::optional<ai::Level> { return std::nullopt; },
                 [](const ComputerSeat& c) -> std::optional<ai::Level> { return c.level; }},
      seat);
}

std::string seatName(const Seat& seat) {
  return std::visit(Overloaded{[](const HumanSeat&) { return std::string("human"); },
                               [](const ComputerSeat& c) {
                                 return kComputerPrefix + std::string(ai::levelName(c.level));
                               }},
                    seat);
}

std::vector<std::string> seatNames() {
  std::vector<std::string> names = {"human"};
  for (const std::string& level : ai::levelNames()) names.push_back(kComputerPrefix + level);
  return names;
}

std::string seatNamesText() {
  return "human or ai:<level> (" + ai::levelNamesText() + ")";
}

std::optional<Seat> seatFromName(const std::string& name) {
  if (name == "human") return Seat(HumanSeat{});
  const std::string prefix = kComputerPrefix;
  if (name.compare(0, prefix.size(), prefix) == 0) {
    if (const auto level = ai::levelFromName(name.substr(prefix.size()))) {
      return Seat(ComputerSeat{*level});
    }
  }
  return std::nullopt;
}

}  // namespace nineball
