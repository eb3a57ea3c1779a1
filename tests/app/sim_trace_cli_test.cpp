// `nineball sim` with a trace, run as a user or a script would.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "app/cli_runner.hpp"

namespace nineball::testing {
namespace {

std::string scene(const std::string& trace) {
  return R"({"balls": [{"id": 0, "x": -0.635, "y": 0.0}, {"id": 3, "x": 0.3, "y": 0.02}],
             "shot": {"heading_deg": 0, "speed": 2.0}, "until": 0.5, "trace": )" +
         trace + "}";
}

std::string oneLine(std::string s) {
  for (char& c : s) {
    if (c == '\n') c = ' ';
  }
  return s;
}

TEST(SimTraceCli, PrintsATracePerBall) {
  const CliOutcome r = runOnDocument("sim", scene(R"({"hz": 100})"));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_TRUE(doc.contains("trace"));
  EXPECT_EQ(doc["trace_truncated"], false);
  ASSERT_EQ(doc["trace"].size(), 2u);
  for (const char* id : {"0", "3"}) {
    const auto& t = doc["trace"][id];
    const std::size_t n = t["t"].size();
    EXPECT_GE(n, 51u);
    for (const char* key : {"x", "y", "vx", "vy", "w", "phase"}) EXPECT_EQ(t[key].size(), n) << key;
    EXPECT_EQ(t["t"].back(), 0.5);
  }
  EXPECT_EQ(doc["trace"]["0"]["phase"][1], "sliding");
}

TEST(SimTraceCli, RefusesBadTraceFieldsWithStatus2) {
  for (const auto& [trace, says] : {std::pair{R"({"hz": 0})", "trace.hz: must be >= 1"},
                                    std::pair{R"({"hz": 5, "events_only": true})", "trace: give"},
                                    std::pair{R"({"step": 5})", "trace.step: unknown field"},
                                    std::pair{R"("fine")", "trace: expected an object"}}) {
    const CliOutcome r = runOnDocument("sim", scene(trace));
    EXPECT_EQ(r.status, 2) << trace;
    EXPECT_EQ(r.out, "") << trace;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  }
}

TEST(SimTraceCli, JsonlCarriesTracesLineByLine) {
  const std::string lines = oneLine(scene(R"({"events_only": true})")) + "\n" +
                            oneLine(scene(R"({"hz": 0})")) + "\n" + oneLine(scene(R"({"hz": 20})"));
  const CliOutcome r = runOnDocument("sim --jsonl", lines);
  EXPECT_EQ(r.status, 2) << r.err;
  std::istringstream out(r.out);
  std::vector<nlohmann::json> docs;
  for (std::string line; std::getline(out, line);) docs.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(docs.size(), 3u);
  ASSERT_TRUE(docs[0].contains("trace"));
  EXPECT_EQ(docs[0]["trace"]["3"]["t"].size(), docs[0]["events"].size());
  EXPECT_NE(docs[1]["error"].get<std::string>().find("trace.hz"), std::string::npos);
  ASSERT_TRUE(docs[2].contains("trace"));
  EXPECT_GE(docs[2]["trace"]["0"]["t"].size(), 11u);
}

}  // namespace
}  // namespace nineball::testing
