#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "io/parse_error.hpp"
#include "nineball/match.hpp"

// A match's state between turns as JSON (online play heals a peer out of step with it). Every
// double keeps its bits: JSON numbers are written shortest-exact and read back exactly.
namespace nineball::io {

nlohmann::ordered_json snapshotToJson(const MatchSnapshot& snapshot);

/// Reads a snapshot sent for a match whose balls are `like` (the same ids, in the same order:
/// a snapshot of another game or rack is refused) on a table of half-size `bound` (m). Every
/// number is checked; throws ParseError naming the field.
MatchSnapshot parseSnapshot(const nlohmann::json& v, const std::vector<BallState>& like,
                            double bound);

}  // namespace nineball::io
