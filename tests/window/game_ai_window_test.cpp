// The computer opponent in the real game window under Xvfb, in eight-ball and ten-ball: the
// opening break, then the computer's own turns for a fixed number of frames, without error.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "support/file_text.hpp"
#include "support/xvfb_run.hpp"

namespace {

using nineball::testing::shellWord;

using nineball::testing::fileText;

struct Run {
  int status = -1;
  std::string err;  // the game's log at info level
};

// Under LeakSanitizer the software GL driver leaks a little from code it cannot name: such
// leaks do not fail the run, a report naming nineball's code does (as the other Xvfb tests).
Run playUnderXvfb(const std::string& game, const std::string& png) {
  const nineball::testing::XvfbRun run =
      nineball::testing::runGameUnderXvfb("--log-level info --opponent ai:easy --game " + game +
                                              " --frames 1200 --screenshot " + shellWord(png),
                                          1280, 800);
  Run r;
  r.status = run.status;
  r.err = run.err;
  return r;
}

void expectComputerTurns(const std::string& game) {
  SCOPED_TRACE(game);
  ASSERT_EQ(std::system("command -v xvfb-run >/dev/null 2>&1"), 0)
      << "xvfb-run not found: install xvfb and xauth (bash scripts/setup.sh)";
  const std::string png = "/tmp/nineball-test-ai-" + game + "-" + std::to_string(getpid()) + ".png";
  const Run r = playUnderXvfb(game, png);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fileText(png).empty()) << "no screenshot";
  std::remove(png.c_str());
  EXPECT_NE(r.err.find("opponent: vs computer (casual)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Computer shoots:"), std::string::npos) << r.err;  // its own turn
  for (const char* bad : {"error", "refused", "cannot play"}) {
    EXPECT_EQ(r.err.find(bad), std::string::npos) << bad << " in:\n" << r.err;
  }
  if (r.err.find("LeakSanitizer") != std::string::npos) {
    EXPECT_EQ(r.err.find("nineball::"), std::string::npos) << r.err;
  }
}

TEST(ComputerWindow, PlaysEightBallUnderXvfb) {
  expectComputerTurns("eight-ball");
}

TEST(ComputerWindow, PlaysTenBallUnderXvfb) {
  expectComputerTurns("ten-ball");
}

}  // namespace
