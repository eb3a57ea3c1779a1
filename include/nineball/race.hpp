#pragma once

#include <array>
#include <optional>

#include "nineball/match.hpp"
#include "nineball/rules.hpp"

// A match of several racks (pool) or frames (snooker): the first to win `race_to` of them wins.
// The window and `nineball match` rack and open each one the same way, so a match saved in one
// plays again in the other.
namespace nineball {

/// Who opens the racks after the first. WPA's standard format alternates the break (and WPBSA's
/// frames alternate the break-off); leagues often let the winner of a rack break the next.
enum class BreakOrder { Alternate, Winner };

const char* breakOrderName(BreakOrder order);  ///< "alternate" or "winner"
std::optional<BreakOrder> breakOrderFromName(const char* name);

/// The length of a match and how its racks are opened. race_to 0: a single rack.
struct Race {
  int race_to = 0;
  BreakOrder breaks = BreakOrder::Alternate;
};

/// The most racks a race may be to (a best of 199 racks).
constexpr int kLongestRace = 99;

/// Who opens rack `index` (0 the first): A the first; then A and B in turn, or the winner of the
/// rack before (`last_winner`, A when it had none).
rules::Player rackOpener(BreakOrder order, int index, std::optional<rules::Player> last_winner);

/// Rack `index` of a match whose first rack is `first`: the later racks are racked afresh (a
/// layout given for the first is not kept) from the seed `first.seed + index`, opened by `opener`.
MatchSetup rackSetup(const MatchSetup& first, int index, rules::Player opener);

/// Racks won by A and B, and the winner once one reaches `race.race_to` (none for a single rack).
struct RaceScore {
  std::array<int, 2> won{};
  std::optional<rules::Player> winner(const Race& race) const;
  void count(std::optional<rules::Player> rack_winner);
};

}  // namespace nineball
