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

namespace nineball::testing {
namespace {

// Counts the occurrences of `what` in `text`.
std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Basic well-formedness: one root <svg> element, and every element opened is closed, in
// order (self-closing ones aside); comments, declarations and text are skipped.
::testing::AssertionResult wellFormed(const std::string& svg) {
  std::vector<std::string> open;
  std::size_t roots = 0;
  for (std::size_t at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
    const std::size_t end = svg.find('>', at);
    if (end == std::string::npos) return ::testing::AssertionFailure() << "unclosed tag";
    const std::string tag = svg.substr(at + 1, end - at - 1);
    if (tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (open.empty() || open.back() != name) {
        return ::testing::AssertionFailure() << "</" << name << "> closes nothing open";
      }
      open.pop_back();
      continue;
    }
    const std::string name = tag.substr(0, tag.find_first_of(" \n/"));
    if (open.empty()) ++roots;
    if (open.empty() && name != "svg") return ::testing::AssertionFailure() << "root " << name;
    if (count(tag, "\"") % 2 != 0) return ::testing::AssertionFailure() << "quotes in " << tag;
    if (tag.back() != '/') open.push_back(name);
  }
  if (!open.empty()) return ::testing::AssertionFailure() << "<" << open.back() << "> not closed";
  if (roots != 1) return ::testing::AssertionFailure() << roots << " roots";
  return ::testing::AssertionSuccess();
}

std::string shot() {
  // The cue ball into the 3, which runs on towards the top-right pocket; the 5 stays put.
  return R"({"balls": [{"id": 0, "x": -0.6, "y": 0.0}, {"id": 3, "x": 0.2, "y": 0.1},
                       {"id": 5, "x": -0.3, "y": -0.4}],
             "shot": {"heading_deg": 7.125, "speed": 3.0, "tip": [0, -0.3]}})";
}

TEST(SimSvgCli, DrawsOnePathPerMovingBallAndAMarkerPerEvent) {
  TempFile picture;
  const CliOutcome r = runOnDocument("sim --svg " + shellQuoted(picture.path()), shot());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_FALSE(doc.contains("trace")) << "the picture's own trace is not printed";
  const std::string svg = picture.read();
  EXPECT_TRUE(wellFormed(svg));
  EXPECT_EQ(count(svg, "class=\"ball-path\""), 2u) << "the cue ball and the 3 move, the 5 not";
  EXPECT_EQ(count(svg, "data-ball=\"5\""), 0u);
  std::size_t events = 0, contacts = 0, cushions = 0, pockets = 0;
  for (const auto& e : doc["events"]) {
    const std::string type = e["type"];
    if (type == "rest") continue;
    ++events;
    contacts += type == "ball";
    cushions += type == "cushion";
    pockets += type == "pocket";
  }
  ASSERT_GE(contacts, 1u);
  ASSERT_GE(cushions, 1u);
  EXPECT_EQ(count(svg, "class=\"event "), events);
  EXPECT_EQ(count(svg, "class=\"event ball\""), contacts);
  EXPECT_EQ(count(svg, "class=\"event cushion\""), cushions);
  EXPECT_EQ(count(svg, "class=\"event pocket\""), pockets);
  EXPECT_EQ(count(svg, "class=\"pocket\""), 6u) << "six pocket openings";
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos) << "the cue ball slides first";
}

TEST(SimSvgCli, KeepsTheScenesOwnTraceInTheResult) {
  TempFile picture;
  std::string scene = shot();
  scene.insert(scene.rfind('}'), R"(, "trace": {"events_only": true})");
  const CliOutcome r = runOnDocument("sim --svg " + shellQuoted(picture.path()), scene);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_TRUE(doc.contains("trace"));
  EXPECT_LE(doc["trace"]["0"]["t"].size(), doc["events"].size());
  EXPECT_TRUE(wellFormed(picture.read()));
}

TEST(SimSvgCli, RefusesAnUnwritableFileBeforeSimulating) {
  // The scene is bad too: the file is refused first, so the scene was never read.
  const CliOutcome r = runOnDocument("sim --svg /nonexistent_nineball_dir/shot.svg", "{");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("--svg: cannot write /nonexistent_nineball_dir/shot.svg"), std::string::npos)
      << r.err;
  const CliOutcome empty = runOnDocument("sim --svg ''", shot());
  EXPECT_EQ(empty.status, 2);
  EXPECT_NE(empty.err.find("--svg: no file name given"), std::string::npos) << empty.err;
  const CliOutcome lines = runOnDocument("sim --jsonl --svg x.svg", shot());
  EXPECT_EQ(lines.status, 2);
  EXPECT_NE(lines.err.find("--jsonl"), std::string::npos) << lines.err;
}

TEST(SimSvgCli, ABadSceneWritesNoPicture) {
  TempFile dir_probe;
  const std::string path = dir_probe.path() + ".svg";
  const CliOutcome r = runOnDocument("sim --svg " + shellQuoted(path), R"({"balls": 1})");
  EXPECT_EQ(r.status, 2);
  std::ifstream in(path);
  EXPECT_FALSE(in.good()) << "nothing written for a refused scene";
}

}  // namespace
}  // namespace nineball::testing
