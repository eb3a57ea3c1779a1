#pragma once

#include <optional>
#include <string>

namespace nineball::app {

/// The running program's own file (from /proc/self/exe, so symlinks are resolved); nothing,
/// with the reason in `why`, when it cannot be read.
std::optional<std::string> executablePath(std::string& why);

}  // namespace nineball::app
