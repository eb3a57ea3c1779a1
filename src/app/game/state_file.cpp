#include "app/game/state_file.hpp"

#include <filesystem>
#include <system_error>

#include "nineball/atomic_file.hpp"

namespace nineball::app {

bool saveStateFile(const std::string& path, const std::string& text, const std::string& no_home,
                   std::string& why) {
  if (path.empty()) {
    why = no_home;
    return false;
  }
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) {
    why = "cannot make " + folder.string() + ": " + ec.message();
    return false;
  }
  return writeFileAtomically(path, text, why);
}

}  // namespace nineball::app
