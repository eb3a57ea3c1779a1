#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "io/match_json.hpp"

namespace nineball::app {

/// Reads and parses a match script from a file or "-" (standard input). On failure prints
/// "<prefix><file>: <reason>" on `err` and gives nothing.
/// `text`, when given, receives the script as read.
std::optional<io::MatchScript> loadMatchScript(const std::string& path, std::istream& in,
                                               std::ostream& err, const std::string& prefix,
                                               std::string* text = nullptr);

}  // namespace nineball::app
