#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "io/match_json.hpp"

namespace nineball::app {

/// Reads and parses a match script from a file or "-" (standard input). On failure prints
/// "<prefix><file>: <reason>" on `err` and gives nothing.
std::optional<io::MatchScript> loadMatchScript(const std::string& path, std::istream& in,
                                               std::ostream& err, const std::string& prefix);

}  // namespace nineball::app
