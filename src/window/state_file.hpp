#pragma once

#include <cstddef>
#include <string>

namespace nineball::window {

/// Writes a file of the game's own (settings, the saved rack) whole or not at all, making its
/// folder first. An empty path means the environment names no home for it: `no_home` says so.
bool saveStateFile(const std::string& path, const std::string& text, const std::string& no_home,
                   std::string& why);

/// The game's own files are small; past this (bytes) one is not read but refused.
constexpr std::size_t kMaxStateFileBytes = 1u << 20;

/// Reads a file of the game's own whole into `text`, refusing one larger than
/// kMaxStateFileBytes. False with `why` (nothing there, unreadable, or too large).
bool readStateFile(const std::string& path, std::string& text, std::string& why);

/// Text that is safe to write into a JSON string and into a log line: malformed UTF-8 becomes
/// '?' (nlohmann throws on it when it writes).
std::string printable(const std::string& s);

}  // namespace nineball::window
