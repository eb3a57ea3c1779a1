// Runs the real nineball binary, as a user or a script would.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"

namespace {

using nineball::testing::TempFile;
using Outcome = nineball::testing::CliOutcome;

std::string quoted(const std::string& s) {
  return nineball::testing::shellQuoted(s);
}

Outcome run(const std::string& args, const std::string& stdin_path = "/dev/null") {
  return nineball::testing::runNineball(args, stdin_path);
}

const char* kGoodScene = R"({
  "balls": [{"id": 0, "x": -0.635, "y": 0.0}, {"id": 1, "x": 0.3, "y": 0.02}],
  "shot": {"heading_deg": 0, "speed": 2.0},
  "until": 0.5
})";

std::vector<std::string> keysOf(const nlohmann::ordered_json& j) {
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  return keys;
}

TEST(SimCli, PrintsTheResultOfAGoodScene) {
  TempFile scene(kGoodScene);
  const Outcome r = run("sim " + quoted(scene.path()));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(keysOf(doc), (std::vector<std::string>{"time", "steps", "wall_ms", "end", "partial",
                                                   "balls", "events"}));
  ASSERT_EQ(doc["balls"].size(), 2u);
  EXPECT_EQ(doc["balls"][0]["id"], 0);
  EXPECT_EQ(doc["balls"][1]["id"], 1);
  EXPECT_GT(doc["steps"].get<long>(), 0);
}

TEST(SimCli, ReadsStandardInputAndGivesTheSameResult) {
  TempFile scene(kGoodScene);
  const Outcome from_file = run("sim " + quoted(scene.path()));
  const Outcome from_stdin = run("sim -", scene.path());
  ASSERT_EQ(from_stdin.status, 0) << from_stdin.err;
  auto a = nlohmann::json::parse(from_file.out);
  auto b = nlohmann::json::parse(from_stdin.out);
  // Wall time is the one field that may differ between two runs.
  a.erase("wall_ms");
  b.erase("wall_ms");
  EXPECT_EQ(a, b);
}

TEST(SimCli, RefusesBadScenesWithStatus2AndNothingOnStdout) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"balls\": [", "invalid JSON"},
      {"", "empty input"},
      {R"({"balls": [], "colour": 1})", "colour: unknown field"},
      {R"({"balls": [{"id": 0, "x": "left", "y": 0}]})", "balls[0].x: expected a number"},
      {R"({"balls": [{"id": 0, "x": 0, "y": 0}, {"id": 1, "x": 0.01, "y": 0}]})", "balls[1]"},
      {R"({"balls": [{"id": 0, "x": 9, "y": 0}]})", "balls[0]"},
  };
  for (const auto& [text, reason] : cases) {
    TempFile scene(text);
    const Outcome r = run("sim " + quoted(scene.path()));
    EXPECT_EQ(r.status, 2) << text;
    EXPECT_EQ(r.out, "") << text;
    EXPECT_EQ(r.err.rfind("nineball sim: " + scene.path() + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
  }
}

TEST(SimCli, RefusesBadStandardInput) {
  TempFile scene("{\"balls\": 3}");
  const Outcome r = run("sim -", scene.path());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("balls: expected an array"), std::string::npos) << r.err;
  const Outcome empty = run("sim -");
  EXPECT_EQ(empty.status, 2);
  EXPECT_EQ(empty.out, "");
}

TEST(SimCli, RefusesAMissingFile) {
  const Outcome r = run("sim /nonexistent/nineball/scene.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("cannot open"), std::string::npos) << r.err;
}

TEST(SimCli, HelpExitsZero) {
  const Outcome top = run("--help");
  EXPECT_EQ(top.status, 0);
  EXPECT_NE(top.out.find("sim"), std::string::npos);
  const Outcome sim = run("sim --help");
  EXPECT_EQ(sim.status, 0);
  EXPECT_NE(sim.out.find("scene"), std::string::npos);
}

TEST(SimCli, UsageErrorsExit2) {
  for (const std::string args :
       {"--no-such-option", "sim", "sim a.json b.json", "frobnicate", "--log-level loud sim -",
        "break --speed fast", "break --seed -1"}) {
    const Outcome r = run(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(r.out, "") << args;
    EXPECT_FALSE(r.err.empty()) << args;
  }
}

TEST(SimCli, AcceptsALogLevelBeforeOrAfterTheCommand) {
  TempFile scene(kGoodScene);
  EXPECT_EQ(run("--log-level off sim " + quoted(scene.path())).status, 0);
  EXPECT_EQ(run("sim " + quoted(scene.path()) + " --log-level error").status, 0);
}

TEST(SimCli, BreakPrintsASummaryOrJson) {
  const Outcome summary = run("break");
  ASSERT_EQ(summary.status, 0) << summary.err;
  EXPECT_NE(summary.out.find("Pocketed"), std::string::npos) << summary.out;
  EXPECT_NE(summary.out.find("Cue ball"), std::string::npos) << summary.out;
  const Outcome json = run("break --seed 3 --speed 8 --json");
  ASSERT_EQ(json.status, 0) << json.err;
  const auto doc = nlohmann::json::parse(json.out);
  EXPECT_EQ(doc["balls"].size(), 10u);
}

TEST(SimCli, JsonlGivesOneLinePerSceneAndGoesOnPastABadOne) {
  std::string one_line = kGoodScene;
  std::replace(one_line.begin(), one_line.end(), '\n', ' ');
  const std::string bad_place = R"({"balls": [{"id": 0, "x": 9, "y": 0}]})";
  TempFile lines(one_line + "\n\nnot json\n" + bad_place + "\n" + one_line + "\n");
  const Outcome r = run("sim --jsonl " + quoted(lines.path()));
  EXPECT_EQ(r.status, 2) << r.err;
  std::istringstream out(r.out);
  std::vector<nlohmann::ordered_json> docs;
  for (std::string line; std::getline(out, line);)
    docs.push_back(nlohmann::ordered_json::parse(line));
  ASSERT_EQ(docs.size(), 4u) << "the blank line gets nothing, every other line one line";
  EXPECT_EQ(docs[0]["balls"].size(), 2u);
  EXPECT_EQ(docs[1]["line"], 3);
  EXPECT_NE(docs[1]["error"].get<std::string>().find("invalid JSON"), std::string::npos);
  EXPECT_EQ(docs[2]["line"], 4);
  EXPECT_NE(docs[2]["error"].get<std::string>().find("balls[0]"), std::string::npos);
  EXPECT_EQ(docs[3]["balls"], docs[0]["balls"]) << "the same scene, the same result";
  EXPECT_NE(r.err.find("2 of 4 scenes refused"), std::string::npos) << r.err;
}

// A line past the 4 MiB bound is refused by its number without being held (it was read whole
// first: a 64 MiB line cost 136 MB), and the next line is read; a line that never ends
// (/dev/zero, which grew to 2.1 GB) stops the input after a bounded skip.
TEST(SimCli, JsonlRefusesAnOverlongLineWithoutHoldingItAndGoesOn) {
  std::string one_line = kGoodScene;
  std::replace(one_line.begin(), one_line.end(), '\n', ' ');
  TempFile lines(std::string(64u << 20, ' ') + "x\n" + one_line + "\n");
  const Outcome r = run("sim --jsonl " + quoted(lines.path()));
  EXPECT_EQ(r.status, 2) << r.err;
  std::istringstream out(r.out);
  std::vector<nlohmann::ordered_json> docs;
  for (std::string line; std::getline(out, line);) {
    docs.push_back(nlohmann::ordered_json::parse(line));
  }
  ASSERT_EQ(docs.size(), 2u);
  EXPECT_EQ(docs[0]["line"], 1);
  EXPECT_NE(docs[0]["error"].get<std::string>().find("larger than 4 MiB"), std::string::npos);
  EXPECT_EQ(docs[1]["balls"].size(), 2u);

  const Outcome endless = run("sim --jsonl /dev/zero");
  EXPECT_EQ(endless.status, 2);
  EXPECT_NE(endless.err.find("line 1: larger than 4 MiB"), std::string::npos) << endless.err;
  EXPECT_NE(endless.err.find("read no further"), std::string::npos) << endless.err;
}

TEST(SimCli, JsonlMatchesTheSingleSceneResultAndExitsZeroWhenAllAreGood) {
  std::string one_line = kGoodScene;
  std::replace(one_line.begin(), one_line.end(), '\n', ' ');
  TempFile single(kGoodScene);
  TempFile lines(one_line + "\n" + one_line);  // the last line needs no newline
  const Outcome r = run("sim --jsonl " + quoted(lines.path()));
  ASSERT_EQ(r.status, 0) << r.err;
  const Outcome alone = run("sim " + quoted(single.path()));
  auto expected = nlohmann::ordered_json::parse(alone.out);
  std::istringstream out(r.out);
  int count = 0;
  for (std::string line; std::getline(out, line); ++count) {
    auto doc = nlohmann::ordered_json::parse(line);
    doc.erase("wall_ms");
    expected.erase("wall_ms");
    EXPECT_EQ(doc, expected);
  }
  EXPECT_EQ(count, 2);
  EXPECT_EQ(run("sim --jsonl /nonexistent/scenes.jsonl").status, 2);
}

}  // namespace

namespace nineball::testing {
namespace {

// Small things the campaign found: a full stdout exited 1 and said nothing; a usage error took
// two lines; `break --speed` took up to 100 m/s where every other speed stops at 14.
TEST(CliEdges, AFullStdoutIsSaidAUsageErrorIsOneLineAndBreakSpeedsAreBounded) {
  TempFile scene(R"({"balls": [{"id": 0, "x": 0, "y": 0}], "shot": {"heading_deg": 0,
                     "speed": 1}})");
  const CliOutcome full = runNineball("sim " + shellQuoted(scene.path()) + " >/dev/full");
  EXPECT_EQ(full.status, 2);
  EXPECT_EQ(full.err, "nineball: cannot write to standard output: No space left on device\n");

  const CliOutcome usage = runNineball("sim --no-such-option");
  EXPECT_EQ(usage.status, 2);
  EXPECT_EQ(std::count(usage.err.begin(), usage.err.end(), '\n'), 1) << usage.err;

  const CliOutcome fast = runNineball("break --speed 14.5");
  EXPECT_EQ(fast.status, 2);
  EXPECT_NE(fast.err.find("from 0 to 14"), std::string::npos) << fast.err;
  EXPECT_EQ(runNineball("break --speed 14").status, 0);
}

}  // namespace
}  // namespace nineball::testing
