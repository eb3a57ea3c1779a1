#pragma once

#include <optional>
#include <string>
#include <variant>

#include "nineball/planner.hpp"

namespace nineball {

/// A person plays the seat: at this computer in the window, from the script's turns in
/// nineball match.
struct HumanSeat {
  bool operator==(const HumanSeat&) const { return true; }
  bool operator!=(const HumanSeat&) const { return false; }
};

/// The computer plays the seat, with the planner at a level.
struct ComputerSeat {
  ai::Level level = ai::Level::Club;

  bool operator==(const ComputerSeat& o) const { return level == o.level; }
  bool operator!=(const ComputerSeat& o) const { return level != o.level; }
};

/// Who plays one side of the table. Another kind of player is one more alternative here; the
/// helpers below visit every alternative, so the compiler points at each of them that must
/// learn it. A player at another computer is not one: online, each side's own seat is a person
/// or the computer here, and the other seat's turns come over the link (src/net; the window's
/// OnlinePlay), which carries each turn's Seat by name.
using Seat = std::variant<HumanSeat, ComputerSeat>;

/// True when the computer plays the seat.
bool isComputer(const Seat& seat);
/// The computer's level; nothing when the computer does not play the seat.
std::optional<ai::Level> computerLevel(const Seat& seat);
/// "human" or "ai:" and the level's name ("ai:club"): the seat's name in the JSON contracts (the
/// match script's "players", the window's --opponent, the settings and the saved rack).
std::string seatName(const Seat& seat);
/// Reads a seat's name; nothing for an unknown one.
std::optional<Seat> seatFromName(const std::string& name);
/// Every name seatFromName takes: "human", then "ai:" and each level's name or older name.
std::vector<std::string> seatNames();
/// The same for a message: "human or ai:<level> (beginner, ...)".
std::string seatNamesText();

}  // namespace nineball
