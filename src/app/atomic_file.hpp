#pragma once

#include <string>

namespace nineball::app {

/// Writes the file whole or not at all: to a temporary name beside it, then renamed over it.
/// Returns false (and leaves nothing behind) when it cannot.
bool writeFileAtomically(const std::string& path, const std::string& content);

}  // namespace nineball::app
