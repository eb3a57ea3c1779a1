#pragma once

#include <functional>
#include <string>

namespace nineball {

/// Writes a file whole or not at all. The data go to a fresh temporary file in the target's
/// directory (mkstemp: a unique name, never an existing file or a symlink), are flushed,
/// fsynced and checked, and the temporary file is then renamed over the target. The target may
/// be new, a regular file, or a symlink to a regular file or to nothing (the link is replaced,
/// not followed); a directory, device, FIFO or socket, or a symlink to one, is refused before
/// anything is written. On any failure, or if the process is stopped by
/// SIGINT, SIGTERM or SIGHUP while writing, the temporary file is removed. False with `why`
/// naming `path` and the reason.
bool writeFileAtomically(const std::string& path, const std::string& content, std::string& why);

/// The same for a writer that can only write to a named file (an image library): `write` is
/// given the temporary file's name (which ends in `suffix`, so that a library choosing the
/// format by extension sees the right one) and returns whether it succeeded; `check` is then
/// given it to read back and confirm it whole before the rename.
bool writeFileAtomicallyWith(const std::string& path, const std::string& suffix,
                             const std::function<bool(const std::string&)>& write,
                             const std::function<bool(const std::string&)>& check,
                             std::string& why);

/// Whether a file could be created at `path` now (its directory exists and is writable), so
/// that a long run can refuse a destination before it starts. False with `why` naming it.
bool canWriteFile(const std::string& path, std::string& why);

}  // namespace nineball
