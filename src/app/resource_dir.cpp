#include "app/resource_dir.hpp"

#include <filesystem>
#include <ostream>
#include <system_error>

#include "app/executable_path.hpp"
#include "app/exit_codes.hpp"

// Both come from CMakeLists.txt, for this file only.
#ifndef NINEBALL_RESOURCES_FROM_BIN
#error "NINEBALL_RESOURCES_FROM_BIN (e.g. ../share/nineball) must be defined"
#endif
#ifndef NINEBALL_SOURCE_RESOURCES
#error "NINEBALL_SOURCE_RESOURCES (the source tree's resources/) must be defined"
#endif

namespace nineball::app {
namespace {

namespace fs = std::filesystem;

bool holdsIcon(const fs::path& dir) {
  std::error_code ec;  // an unreadable folder is no resource folder, not an error
  return fs::is_regular_file(dir / kIconFile, ec);
}

}  // namespace

std::string installedResourceDir(const std::string& exe_path) {
  return (fs::path(exe_path).parent_path() / NINEBALL_RESOURCES_FROM_BIN)
      .lexically_normal()
      .string();
}

std::optional<std::string> findResourceDir(const std::string& exe_path,
                                           const std::string& source_resources) {
  // The installed folder first: an installed nineball must not pick up a source tree that
  // happens to still exist where it was built.
  if (!exe_path.empty()) {
    const std::string installed = installedResourceDir(exe_path);
    if (holdsIcon(installed)) return installed;
  }
  if (holdsIcon(source_resources)) return source_resources;
  return std::nullopt;
}

std::optional<std::string> findResourceDir() {
  std::string why;
  const auto self = executablePath(why);
  // Without its own path the program can still be run from the source tree's build.
  return findResourceDir(self.value_or(""), NINEBALL_SOURCE_RESOURCES);
}

int printResourceDir(std::ostream& out, std::ostream& err) {
  const auto dir = findResourceDir();
  if (!dir) {
    err << "nineball: no resource folder found (neither installed beside this program nor "
           "the source tree's resources/)\n";
    return kExitInternal;
  }
  out << *dir << '\n';
  return kExitOk;
}

}  // namespace nineball::app
