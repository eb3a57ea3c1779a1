#include "common/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <vector>

namespace nineball {
namespace {

// The temporary file being written, for the signal handler: a fixed buffer, since a handler
// may only touch what is async-signal-safe.
char g_pending[4096];
std::atomic<bool> g_has_pending{false};

extern "C" void removePendingAndDie(int sig) {
  if (g_has_pending.load()) ::unlink(g_pending);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

class PendingFile {
 public:
  explicit PendingFile(const std::string& name) {
    if (name.size() >= sizeof g_pending) return;
    std::memcpy(g_pending, name.c_str(), name.size() + 1);
    g_has_pending.store(true);
    for (int sig : {SIGINT, SIGTERM, SIGHUP})
      previous_.push_back(std::signal(sig, removePendingAndDie));
  }
  ~PendingFile() {
    g_has_pending.store(false);
    int i = 0;
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, previous_[i++]);
  }
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

 private:
  std::vector<void (*)(int)> previous_;
};

std::string directoryOf(const std::string& path) {
  const auto slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string baseName(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string reason(int err) {
  return std::strerror(err);
}

const char* kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// The one rule for what a written file may replace: nothing, a regular file, or a symlink to a
// regular file or to nothing (the link itself is replaced, not followed). A directory, a
// device, a FIFO or a socket, or a symlink to one, is refused: renaming over it would put a
// regular file where a device or a pipe was.
bool replaceable(const std::string& path, std::string& why) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return true;  // nothing there yet
  if (S_ISREG(st.st_mode)) return true;
  if (S_ISLNK(st.st_mode)) {
    struct stat to {};
    if (::stat(path.c_str(), &to) != 0 || S_ISREG(to.st_mode)) return true;
    why = std::string("cannot write ") + path + ": it is a symlink to " + kindOf(to.st_mode) +
          " (only a regular file, a symlink to one, or a new name is replaced)";
    return false;
  }
  why = std::string("cannot write ") + path + ": it is " + kindOf(st.st_mode) +
        " (only a regular file, a symlink to one, or a new name is replaced)";
  return false;
}

// A fresh temporary file beside `path`; returns its descriptor and sets `name`, or -1 with
// `why` set.
int createTemporary(const std::string& path, const std::string& suffix, std::string& name,
                    std::string& why) {
  if (path.empty()) {
    why = "no file name given";
    return -1;
  }
  if (path.back() == '/') {
    why = "cannot write " + path + ": it names a directory";
    return -1;
  }
  if (!replaceable(path, why)) return -1;
  std::string base = baseName(path);
  if (base.size() > 64) base.resize(64);
  std::vector<char> tmpl;
  const std::string pattern = directoryOf(path) + "/." + base + ".XXXXXX" + suffix;
  tmpl.assign(pattern.begin(), pattern.end());
  tmpl.push_back('\0');
  const int fd = ::mkstemps(tmpl.data(), static_cast<int>(suffix.size()));
  if (fd < 0) {
    why = "cannot write " + path + ": " + reason(errno);
    return -1;
  }
  name.assign(tmpl.data());
  return fd;
}

bool writeAll(int fd, const std::string& content) {
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;
      return false;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

bool syncAndClose(int fd) {
  const bool synced = ::fsync(fd) == 0;
  const int err = errno;
  const bool closed = ::close(fd) == 0;
  if (!synced) errno = err;
  return synced && closed;
}

bool fail(const std::string& tmp, const std::string& path, std::string& why, int err) {
  ::unlink(tmp.c_str());
  why = "cannot write " + path + ": " + reason(err);
  return false;
}

bool finish(const std::string& tmp, const std::string& path, std::string& why) {
  // mkstemp makes the file 0600; a written file gets the usual permissions.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(tmp.c_str(), 0666 & ~mask);
  // Checked again: a device or FIFO may have been put there while the file was written.
  if (!replaceable(path, why)) {
    ::unlink(tmp.c_str());
    return false;
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) return fail(tmp, path, why, errno);
  return true;
}

}  // namespace

bool writeFileAtomically(const std::string& path, const std::string& content, std::string& why) {
  std::string tmp;
  const int fd = createTemporary(path, "", tmp, why);
  if (fd < 0) return false;
  PendingFile pending(tmp);
  if (!writeAll(fd, content)) {
    const int err = errno;
    ::close(fd);
    return fail(tmp, path, why, err);
  }
  if (!syncAndClose(fd)) return fail(tmp, path, why, errno);
  return finish(tmp, path, why);
}

bool writeFileAtomicallyWith(const std::string& path, const std::string& suffix,
                             const std::function<bool(const std::string&)>& write,
                             const std::function<bool(const std::string&)>& check,
                             std::string& why) {
  std::string tmp;
  const int fd = createTemporary(path, suffix, tmp, why);
  if (fd < 0) return false;
  PendingFile pending(tmp);
  if (!write(tmp)) {
    ::close(fd);
    return fail(tmp, path, why, ENOSPC);
  }
  // The writer wrote through its own handle to the same file: syncing ours flushes it.
  if (!syncAndClose(fd)) return fail(tmp, path, why, errno);
  if (!check(tmp)) {
    ::unlink(tmp.c_str());
    why = "cannot write " + path + ": the file read back is not whole (disk full?)";
    return false;
  }
  return finish(tmp, path, why);
}

bool canWriteFile(const std::string& path, std::string& why) {
  std::string tmp;
  const int fd = createTemporary(path, "", tmp, why);
  if (fd < 0) return false;
  ::close(fd);
  ::unlink(tmp.c_str());
  return true;
}

}  // namespace nineball
