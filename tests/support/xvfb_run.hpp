#pragma once

// The game binary run under a fresh virtual display (xvfb-run), for the tests that look at its
// pictures.
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace nineball::testing {

/// The window size the picture tests draw at, unless a test needs another.
inline constexpr unsigned kWidth = 1280;
inline constexpr unsigned kHeight = 800;
/// The smaller window some tests draw at (960 x 600, the default window's size).
inline constexpr unsigned kSmallWidth = 960;
inline constexpr unsigned kSmallHeight = 600;

struct XvfbRun {
  int status = -1;
  std::string err;
};

inline bool haveXvfbRun() {
  return std::system("command -v xvfb-run >/dev/null 2>&1") == 0;
}

/// `s` in single quotes for the shell.
inline std::string shellWord(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// Runs `command` (a shell command line, its words quoted) on a virtual screen of
/// screen_width x screen_height, with `env` (VAR=value ...) set, its stderr kept in the result.
/// -a searches for a free display from a number of this run's own, so that suites started
/// together do not race for one; under LeakSanitizer the software GL driver leaks a little from
/// code it cannot name, which does not fail the run.
inline XvfbRun runUnderXvfb(const std::string& command, unsigned screen_width,
                            unsigned screen_height, const std::string& env = "") {
  // Runs at once from one test (two windows playing each other) keep their own files.
  static std::atomic<int> runs{0};
  const std::string err_path =
      "/tmp/nineball-xvfb-err-" + std::to_string(getpid()) + "-" + std::to_string(runs++);
  const std::string screen = std::to_string(screen_width) + "x" + std::to_string(screen_height);
  const std::string cmd =
      env + " LSAN_OPTIONS=\"${LSAN_OPTIONS:+$LSAN_OPTIONS:}exitcode=0\" xvfb-run -a -n " +
      std::to_string(200 + getpid() % 700) + " -s '-screen 0 " + screen + "x24' " + command +
      " 2>'" + err_path + "'";
  XvfbRun r;
  const int raw = std::system(cmd.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(err_path);
  std::stringstream ss;
  ss << in.rdbuf();
  r.err = ss.str();
  std::remove(err_path.c_str());
  return r;
}

/// Runs NINEBALL_BINARY muted in a window of width x height filling the screen, with `args`.
inline XvfbRun runGameUnderXvfb(const std::string& args, unsigned width, unsigned height,
                                const std::string& env = "") {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  return runUnderXvfb(shellWord(NINEBALL_BINARY) + " --mute --size " + size + " " + args, width,
                      height, env);
}

}  // namespace nineball::testing
