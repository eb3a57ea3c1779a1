#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "nineball/match.hpp"

// A state a host sends to heal is believed only when it is a state the rack could be in: a
// hostile host must not be able to crash the joiner, stall its physics or hand out a win.
namespace nineball::net {

/// Why `healed` (the host's state after turn `turns - 1`) cannot be the rack `match` plays
/// (this side's state after the same turn), or nothing: checked as a scene is (on the table,
/// no overlaps, within the cue's speeds and spins), the cue ball on the table unless in hand,
/// the rules' state consistent with the balls (the balls on the table, the rack's own balls),
/// no winner unless this side's rack is over too, and no count past what `turns` turns make.
std::optional<std::string> healProblem(const MatchSnapshot& healed, const MatchSetup& setup,
                                       const Match& match, std::size_t turns);

}  // namespace nineball::net
