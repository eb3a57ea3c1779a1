// Runs the real nineball binary as a user or a script would, for the CLI contract tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace nineball::testing {

/// A file under $TMPDIR (or /tmp) made with mkstemp, removed again at scope exit.
class TempFile {
 public:
  explicit TempFile(const std::string& content = "") {
    const char* dir = std::getenv("TMPDIR");
    std::string pattern = std::string(dir && *dir ? dir : "/tmp") + "/nineball_cli_XXXXXX";
    const int fd = mkstemp(pattern.data());
    if (fd < 0) throw std::runtime_error("mkstemp failed for " + pattern);
    ::close(fd);
    path_ = pattern;
    std::ofstream(path_, std::ios::binary) << content;
  }
  ~TempFile() { std::remove(path_.c_str()); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::string& path() const { return path_; }
  std::string read() const {
    std::ifstream in(path_, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

 private:
  std::string path_;
};

/// The string quoted for the shell.
inline std::string shellQuoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct CliOutcome {
  int status = -1;
  std::string out;
  std::string err;
};

/// Runs `nineball ARGS` with stdin from `stdin_path` and collects both streams.
/// `prefix` goes before the program ("timeout -s INT 1 ", say).
inline CliOutcome runNineball(const std::string& args, const std::string& stdin_path = "/dev/null",
                              const std::string& prefix = "") {
  TempFile err;
  const std::string command = prefix + shellQuoted(NINEBALL_BINARY) + " " + args + " <" +
                              shellQuoted(stdin_path) + " 2>" + shellQuoted(err.path());
  CliOutcome r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = err.read();
  return r;
}

/// Writes `document` to a file and runs `nineball COMMAND FILE`.
inline CliOutcome runOnDocument(const std::string& command, const std::string& document) {
  TempFile file(document);
  return runNineball(command + " " + shellQuoted(file.path()));
}

}  // namespace nineball::testing
