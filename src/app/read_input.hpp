#pragma once

#include <iosfwd>
#include <optional>
#include <string>

namespace nineball::app {

/// The whole of a file, or of `stdin_stream` when the path is "-"; nothing, with the reason in
/// `why`, when it cannot be read.
std::optional<std::string> readInput(const std::string& path, std::istream& stdin_stream,
                                     std::string& why);

/// How the path reads in a message: "<stdin>" for "-".
inline std::string shownPath(const std::string& path) {
  return path == "-" ? "<stdin>" : path;
}

}  // namespace nineball::app
