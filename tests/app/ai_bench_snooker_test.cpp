// nineball ai-bench --game snooker: the JSON contract of issue 34 (frames of a level against
// itself, breaks and think time) and bad input refused. One frame of a beginner, a second or so.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/cli_runner.hpp"

namespace nineball::testing {
namespace {

TEST(AiBenchSnooker, OneFrameReportsExactlyTheContractsFields) {
  const CliOutcome r = runNineball("ai-bench --json --game snooker --level beginner --racks 1");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(r.out);
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"game", "level", "frames", "mean_break", "high_break",
                                            "centuries", "think_s"}));
  EXPECT_EQ(j["game"], "snooker");
  EXPECT_EQ(j["level"], "beginner");
  EXPECT_EQ(j["frames"], 1);
  // A frame is 147 points at most from pots (and every red potted once).
  EXPECT_GE(j["high_break"].get<int>(), 0);
  EXPECT_LE(j["high_break"].get<int>(), 147);
  EXPECT_LE(j["mean_break"].get<double>(), j["high_break"].get<double>());
  EXPECT_GE(j["centuries"].get<int>(), 0);
  EXPECT_EQ(j["centuries"].get<int>() > 0, j["high_break"].get<int>() >= 100);
  EXPECT_GT(j["think_s"]["max"].get<double>(), 0.0);
  EXPECT_LE(j["think_s"]["median"].get<double>(), j["think_s"]["max"].get<double>());
}

TEST(AiBenchSnooker, TheTextReportNamesFramesAndBreaks) {
  const CliOutcome r = runNineball("ai-bench --game snooker --level beginner --racks 1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("frames: 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("won by the player who broke off"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("centuries"), std::string::npos) << r.out;
}

TEST(AiBenchSnooker, VersusIsRefusedNamingTheOption) {
  const CliOutcome r = runNineball("ai-bench --json --game snooker --versus club,pro --racks 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("--versus"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace nineball::testing
