#include "app/game_launcher.hpp"

#include <limits.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <string>

#include "app/exit_codes.hpp"

namespace nineball::app {

int launchGameWindow(char** argv, std::ostream& err) {
  char self[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) {
    err << "nineball: cannot start the game window: cannot find this program: "
        << std::strerror(errno) << '\n';
    return kExitInternal;
  }
  std::string path(self, static_cast<std::size_t>(n));
  path = path.substr(0, path.rfind('/') + 1) + "nineball-game";
  std::cout.flush();
  err.flush();
  execv(path.c_str(), argv);
  err << "nineball: cannot start the game window: " << path << ": " << std::strerror(errno) << '\n';
  return kExitInternal;
}

}  // namespace nineball::app
