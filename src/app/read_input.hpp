#pragma once

#include <fstream>
#include <iosfwd>
#include <optional>
#include <string>

#include "common/limits.hpp"

namespace nineball::app {

/// The whole of a file, or of `stdin_stream` when the path is "-"; nothing, with the reason in
/// `why`, when it cannot be read or holds more than `limit` bytes.
std::optional<std::string> readInput(const std::string& path, std::istream& stdin_stream,
                                     std::string& why, std::size_t limit = limits::kMaxInputBytes);

/// The stream to read `path` from: `stdin_stream` for "-", else `file` opened on it; nothing,
/// with the reason in `why`, when it cannot be opened.
std::istream* openInput(const std::string& path, std::istream& stdin_stream, std::ifstream& file,
                        std::string& why);

/// Why an input over limits::kMaxInputBytes is refused.
std::string inputTooLarge();

/// How the path reads in a message: "<stdin>" for "-".
inline std::string shownPath(const std::string& path) {
  return path == "-" ? "<stdin>" : path;
}

}  // namespace nineball::app
