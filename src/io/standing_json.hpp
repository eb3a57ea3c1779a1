#pragma once

#include <nlohmann/json.hpp>
#include <optional>

#include "nineball/match.hpp"

// Where a rack joined in the middle stands, as a match script (or a game environment's reset)
// writes it at its top level beside "balls".
namespace nineball::io {

/// The keys of a standing: "shooter", "ball_in_hand", "fouls", "groups", "score".
inline constexpr const char* kStandingKeys[] = {"shooter", "ball_in_hand", "fouls", "groups",
                                                "score"};

/// Reads the standing keys of `doc` (an object); nothing when it has none. Throws ParseError
/// naming the field ("fouls.A: ...", "groups.B: ...").
std::optional<RackStanding> parseStanding(const nlohmann::json& doc);

}  // namespace nineball::io
