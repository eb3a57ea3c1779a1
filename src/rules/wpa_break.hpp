#pragma once

namespace nineball::rules {

/// The fewest object balls a legal WPA break drives to a cushion when none is pocketed: the
/// same in WPA's nine-, ten- and eight-ball rules (each game's "legal break shot").
constexpr int kBreakBallsToRail = 4;

}  // namespace nineball::rules
