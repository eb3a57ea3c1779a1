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
  j["w"] = ordered_json::array({ball.w.x, ball.w.y, ball.w.z});
  j["pocket"] = ball.pocket ? ordered_json(pocketName(*ball.pocket)) : ordered_json(nullptr);
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
    one["w"] = std::move(w);
    one["phase"] = std::move(phase);
    j[std::to_string(b.id)] = std::move(one);
  }
  return j;
}

ordered_json resultToJson(const SimResult& result) {
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
  if (result.trace) {
    j["trace"] = traceToJson(*result.trace);
    j["trace_truncated"] = result.trace->truncated;
  }
  return j;
}

}  // namespace nineball::io
