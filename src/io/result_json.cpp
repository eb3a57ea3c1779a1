#include "io/result_json.hpp"

namespace nineball::io {

using nlohmann::ordered_json;

namespace {

ordered_json pair(Vec2 v) {
  return ordered_json::array({v.x, v.y});
}

}  // namespace

ordered_json ballToJson(const BallState& ball) {
  ordered_json j;
  j["id"] = ball.id;
  j["x"] = ball.pos.x;
  j["y"] = ball.pos.y;
  j["vx"] = ball.vel.x;
  j["vy"] = ball.vel.y;
  j["z"] = ball.z;
  j["vz"] = ball.vz;
  j["w"] = ordered_json::array({ball.w.x, ball.w.y, ball.w.z});
  const bool dropped = ball.pocket && !ball.off_table;
  j["pocket"] = dropped ? ordered_json(pocketName(*ball.pocket)) : ordered_json(nullptr);
  j["off_table"] = ball.off_table;
  return j;
}

ordered_json eventToJson(const Event& event) {
  ordered_json j;
  j["t"] = event.t;
  // The type names are part of the JSON contract, so they are spelled here, not borrowed.
  switch (event.type) {
    case EventType::BallBall:
      j["type"] = "ball";
      j["a"] = event.a;
      j["b"] = event.b;
      j["va"] = pair(event.va);
      j["vb"] = pair(event.vb);
      break;
    case EventType::Cushion:
      j["type"] = "cushion";
      j["ball"] = event.a;
      j["v"] = pair(event.va);
      break;
    case EventType::Pocket:
      j["type"] = "pocket";
      j["ball"] = event.a;
      j["pocket"] = pocketName(event.pocket);
      break;
    case EventType::AllAtRest:
      j["type"] = "rest";
      break;
    case EventType::Miscue:
      j["type"] = "miscue";
      j["ball"] = event.a;
      break;
    case EventType::Airborne:
    case EventType::Land:
    case EventType::OffTable:
      j["type"] = eventTypeName(event.type);  // "airborne", "land", "off_table"
      j["ball"] = event.a;
      j["v"] = pair(event.va);
      break;
  }
  return j;
}

ordered_json traceToJson(const Trace& trace) {
  ordered_json j = ordered_json::object();
  for (const BallTrace& b : trace.balls) {
    ordered_json w = ordered_json::array();
    for (const Vec3& v : b.w) w.push_back(ordered_json::array({v.x, v.y, v.z}));
    ordered_json phase = ordered_json::array();
    for (TracePhase p : b.phase) phase.push_back(tracePhaseName(p));
    ordered_json one;
    one["t"] = b.t;
    one["x"] = b.x;
    one["y"] = b.y;
    one["vx"] = b.vx;
    one["vy"] = b.vy;
    one["z"] = b.z;
    one["vz"] = b.vz;
    one["w"] = std::move(w);
    one["phase"] = std::move(phase);
    j[std::to_string(b.id)] = std::move(one);
  }
  return j;
}

namespace {

ordered_json resultWithoutTrace(const SimResult& result) {
  ordered_json j;
  j["time"] = result.time;
  j["steps"] = result.steps;
  j["wall_ms"] = result.wall_ms;
  j["end"] = simEndName(result.end);
  j["partial"] = result.partial();
  j["balls"] = ordered_json::array();
  for (const BallState& b : result.balls) j["balls"].push_back(ballToJson(b));
  j["events"] = ordered_json::array();
  for (const Event& e : result.events) j["events"].push_back(eventToJson(e));
  return j;
}

// One ball's trace, one array at a time: only one array's nodes exist at once.
void writeBallTrace(std::ostream& out, const BallTrace& b) {
  out << "{\"t\": " << ordered_json(b.t) << ", \"x\": " << ordered_json(b.x)
      << ", \"y\": " << ordered_json(b.y) << ", \"vx\": " << ordered_json(b.vx)
      << ", \"vy\": " << ordered_json(b.vy) << ", \"z\": " << ordered_json(b.z)
      << ", \"vz\": " << ordered_json(b.vz) << ", \"w\": [";
  for (std::size_t i = 0; i < b.w.size(); ++i) {
    out << (i ? "," : "") << ordered_json::array({b.w[i].x, b.w[i].y, b.w[i].z});
  }
  out << "], \"phase\": [";
  for (std::size_t i = 0; i < b.phase.size(); ++i) {
    out << (i ? ",\"" : "\"") << tracePhaseName(b.phase[i]) << '"';
  }
  out << "]}";
}

}  // namespace

ordered_json resultToJson(const SimResult& result) {
  ordered_json j = resultWithoutTrace(result);
  if (result.trace) {
    j["trace"] = traceToJson(*result.trace);
    j["trace_truncated"] = result.trace->truncated;
  }
  return j;
}

void writeResult(std::ostream& out, const SimResult& result, bool indented) {
  std::string head = resultWithoutTrace(result).dump(indented ? 2 : -1);
  if (!result.trace) {
    out << head;
    return;
  }
  // The closing brace (and the line break before it) goes: the trace follows as the last keys.
  head.pop_back();
  while (!head.empty() && (head.back() == '\n' || head.back() == ' ')) head.pop_back();
  const char* const gap = indented ? "\n  " : "";
  const char* const inner = indented ? "\n    " : "";
  out << head << (indented ? ",\n  " : ",") << "\"trace\": {";
  bool first = true;
  for (const BallTrace& b : result.trace->balls) {
    out << (first ? "" : ",") << inner << '"' << b.id << "\": ";
    writeBallTrace(out, b);
    first = false;
  }
  out << (first ? "" : gap) << "}," << gap
      << "\"trace_truncated\": " << (result.trace->truncated ? "true" : "false")
      << (indented ? "\n}" : "}");
}

}  // namespace nineball::io
