#include "app/executable_path.hpp"

#include <limits.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace nineball::app {

std::optional<std::string> executablePath(std::string& why) {
  char self[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) {
    why = std::strerror(errno);
    return std::nullopt;
  }
  return std::string(self, static_cast<std::size_t>(n));
}

}  // namespace nineball::app
