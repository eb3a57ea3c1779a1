// The "trace" field of a scene and of its result.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "io/result_json.hpp"
#include "io/scene_json.hpp"

namespace nineball::io {
namespace {

std::string traceScene(const std::string& trace) {
  return R"({"balls": [{"id": 0, "x": -0.635, "y": 0.0}, {"id": 1, "x": 0.635, "y": 0.1}],
             "shot": {"heading_deg": 0, "speed": 1}, "trace": )" +
         trace + "}";
}

std::string traceRefusal(const std::string& trace) {
  const SceneResult r = parseScene(traceScene(trace));
  const auto* e = std::get_if<ParseError>(&r);
  return e ? e->message : "accepted";
}

TEST(TraceJson, AcceptsARateOrTheEventsAlone) {
  const SceneResult a = parseScene(traceScene(R"({"hz": 200})"));
  ASSERT_TRUE(std::holds_alternative<Scene>(a)) << std::get<ParseError>(a).message;
  EXPECT_EQ(std::get<Scene>(a).trace->hz, 200.0);
  EXPECT_FALSE(std::get<Scene>(a).trace->events_only);
  const SceneResult b = parseScene(traceScene(R"({"events_only": true})"));
  ASSERT_TRUE(std::holds_alternative<Scene>(b));
  EXPECT_TRUE(std::get<Scene>(b).trace->events_only);
  const SceneResult none = parseScene(R"({"balls": []})");
  EXPECT_FALSE(std::get<Scene>(none).trace);
}

TEST(TraceJson, RefusesBadTraceFieldsNamingThem) {
  struct Case {
    const char* trace;
    const char* message;
  };
  for (const Case& c : {
           Case{"200", "trace: expected an object, found 200"},
           Case{"{}", "trace: needs \"hz\" (samples per second) or \"events_only\": true"},
           Case{R"({"hz": 100, "events_only": true})",
                "trace: give either \"hz\" or \"events_only\", not both"},
           Case{R"({"rate": 100})", "trace.rate: unknown field (expected one of: hz, events_only)"},
           Case{R"({"hz": "fast"})", "trace.hz: expected a number, found string \"fast\""},
           Case{R"({"hz": 0})",
                "trace.hz: must be >= 1 and <= 10000 samples per second, found 0 "
                "(a trace holds at most 1000000 samples, balls x instants, and "
                "ends early beyond that)"},
           Case{R"({"hz": 10001})", "trace.hz: must be >= 1 and <= 10000"},
           Case{R"({"hz": -5})", "trace.hz: must be >= 1"},
           Case{R"({"hz": 1e999})", "trace.hz: number 1e999 is out of range"},
           Case{R"({"events_only": false})",
                "trace.events_only: expected true (for samples at a rate give \"hz\" instead), "
                "found false"},
           Case{R"({"events_only": 1})", "trace.events_only: expected true"},
       }) {
    const std::string got = traceRefusal(c.trace);
    EXPECT_EQ(got.rfind(c.message, 0), 0u) << c.trace << " -> " << got;
  }
}

TEST(TraceJson, ResultCarriesOneEntryPerBallKeyedByItsId) {
  SimResult r;
  Trace trace;
  BallTrace b;
  b.id = 7;
  b.t = {0.0, 0.5};
  b.x = {1.0, 2.0};
  b.y = {3.0, 4.0};
  b.vx = {0.5, 0.0};
  b.vy = {0.0, 0.0};
  b.w = {{1.0, 2.0, 3.0}, {}};
  b.phase = {TracePhase::Sliding, TracePhase::Pocketed};
  trace.balls.push_back(b);
  r.trace = trace;
  const auto j = resultToJson(r);
  ASSERT_TRUE(j.contains("trace"));
  EXPECT_EQ(j["trace_truncated"], false);
  const auto& t = j["trace"]["7"];
  EXPECT_EQ(t["t"], nlohmann::ordered_json::array({0.0, 0.5}));
  EXPECT_EQ(t["w"][0], nlohmann::ordered_json::array({1.0, 2.0, 3.0}));
  EXPECT_EQ(t["phase"], nlohmann::ordered_json::array({"sliding", "pocketed"}));
  std::vector<std::string> keys;
  for (const auto& item : t.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"t", "x", "y", "vx", "vy", "z", "vz", "w", "phase"}));
  EXPECT_FALSE(resultToJson(SimResult{}).contains("trace"));
}

}  // namespace
}  // namespace nineball::io

namespace nineball::io {
namespace {

// writeResult streams the trace array by array; what it writes is the same document as
// resultToJson, indented or on one line, with a trace of several balls or none.
TEST(TraceJson, TheStreamedResultIsTheSameDocument) {
  Scene s;
  s.balls = {BallState::at(kCueBall, {-0.5, 0.1}), BallState::at(3, {0.4, -0.2})};
  s.shot = Shot::withSpeed(-20.0, 3.0);
  s.shot->tip = {0.2, -0.3};
  for (bool traced : {true, false}) {
    s.trace = traced ? std::optional<TraceRequest>(TraceRequest{200.0, false}) : std::nullopt;
    const SimResult r = simulate(s);
    for (bool indented : {true, false}) {
      std::ostringstream out;
      writeResult(out, r, indented);
      const std::string text = out.str();
      EXPECT_EQ(nlohmann::ordered_json::parse(text), resultToJson(r)) << traced << indented;
      EXPECT_EQ(text.find('\n') == std::string::npos, !indented);
      if (!traced) {
        EXPECT_EQ(text, resultToJson(r).dump(indented ? 2 : -1));
      }
    }
  }
}

}  // namespace
}  // namespace nineball::io
