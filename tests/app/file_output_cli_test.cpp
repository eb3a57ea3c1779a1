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
