#include "app/game_launcher.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <string>

#include "app/executable_path.hpp"
#include "app/exit_codes.hpp"

namespace nineball::app {

int launchGameWindow(char** argv, std::ostream& err) {
  std::string why;
  const auto self = executablePath(why);
  if (!self) {
    err << "nineball: cannot start the game window: cannot find this program: " << why << '\n';
    return kExitInternal;
  }
  const std::string path = self->substr(0, self->rfind('/') + 1) + "nineball-game";
  std::cout.flush();
  err.flush();
  execv(path.c_str(), argv);
  err << "nineball: cannot start the game window: " << path << ": " << std::strerror(errno) << '\n';
  return kExitInternal;
}

}  // namespace nineball::app
