#pragma once

#include <iosfwd>
#include <optional>
#include <string>

namespace nineball::app {

/// The window icon. Every resource folder holds it: a folder without it is not one.
constexpr const char* kIconFile = "nineball-256.png";

/// Where an installed nineball at `exe_path` keeps its resources: `<prefix>/share/nineball`
/// for `<prefix>/bin/nineball` (the path between them is the install's, from GNUInstallDirs).
std::string installedResourceDir(const std::string& exe_path);

/// The folder of the icon, the desktop entry and the metainfo, for a program at `exe_path`:
/// the installed folder beside it if it holds the icon, else `source_resources` (the source
/// tree's resources/, for a program run from its build folder) if that does; else nothing.
std::optional<std::string> findResourceDir(const std::string& exe_path,
                                           const std::string& source_resources);

/// The same for this program and the source tree it was built from.
std::optional<std::string> findResourceDir();

/// `nineball --resource-dir`: prints the folder found and returns 0, or says that there is
/// none and returns kExitInternal. For the install test and for bug reports.
int printResourceDir(std::ostream& out, std::ostream& err);

}  // namespace nineball::app
