#pragma once

#include <string>

namespace nineball::app {

/// Writes a file of the game's own (settings, the saved rack) whole or not at all, making its
/// folder first. An empty path means the environment names no home for it: `no_home` says so.
bool saveStateFile(const std::string& path, const std::string& text, const std::string& no_home,
                   std::string& why);

}  // namespace nineball::app
