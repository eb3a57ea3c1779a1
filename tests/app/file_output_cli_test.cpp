// Files asked for on the command line: a place that cannot be written is refused at once,
// with exit status 2, nothing on stdout and the file asked for named.
#include <gtest/gtest.h>

#include "app/cli_runner.hpp"

namespace nineball::testing {
namespace {

const std::string kNowhere = "/nonexistent_nineball_dir/out";

TEST(FileOutputCli, BenchRefusesAnUnwritableCsvBeforeMeasuring) {
  const CliOutcome r = runNineball("bench --quick --csv " + kNowhere + ".csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out.substr(0, 200);
  EXPECT_NE(r.err.find(kNowhere + ".csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No such file or directory"), std::string::npos) << r.err;
}

TEST(FileOutputCli, BenchRefusesAnUnwritableSvg) {
  const CliOutcome r = runNineball("bench --quick --svg " + kNowhere + ".svg");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find(kNowhere + ".svg"), std::string::npos) << r.err;
}

TEST(FileOutputCli, AnEmptyScreenshotNameIsRefusedWithoutAWindow) {
  const CliOutcome r = runNineball("--screenshot ''");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("--screenshot"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace nineball::testing

namespace nineball::testing {
namespace {

TEST(GameOptionsCli, SizeErrorsNameTheRule) {
  struct Case {
    const char* size;
    const char* says;
  };
  for (const Case& c :
       {Case{"0x0", "width 0 is too small"}, Case{"100x100", "width 100 is too small"},
        Case{"640x100", "height 100 is too small"}, Case{"99999x99999", "width 99999 is too large"},
        Case{"800x9000", "height 9000 is too large"}, Case{"800", "expected WIDTHxHEIGHT"},
        Case{"80x0x6", "expected WIDTHxHEIGHT"}}) {
    const CliOutcome r = runNineball(std::string("--size ") + c.size);
    EXPECT_EQ(r.status, 2) << c.size;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.size << ": " << r.err;
    if (std::string(c.says).find("too") != std::string::npos) {
      EXPECT_NE(r.err.find("the width must be 320-8192 and the height 240-8192"), std::string::npos)
          << r.err;
    }
  }
}

TEST(GameOptionsCli, AScreenshotNameMustSayItsFormat) {
  const CliOutcome r = runNineball("--screenshot shot.txt");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(".png, .jpg, .jpeg, .bmp or .tga"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace nineball::testing
