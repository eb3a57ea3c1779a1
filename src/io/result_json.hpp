#pragma once

#include <nlohmann/json.hpp>

#include "nineball/sim.hpp"

namespace nineball::io {

/// The result document of `nineball sim` (design.md, "Headless interface"), keys in the
/// design's order: {"time", "steps", "wall_ms", "end", "partial", "balls", "events"}, then
/// {"trace", "trace_truncated"} when the scene asked for a trace.
nlohmann::ordered_json resultToJson(const SimResult& result);

/// {"<id>": {"t": [...], "x", "y", "vx", "vy", "w": [[wx, wy, wz], ...], "phase": [...]}, ...}.
nlohmann::ordered_json traceToJson(const Trace& trace);

/// {"id", "x", "y", "vx", "vy", "pocket": null | "top-left" | ...}.
nlohmann::ordered_json ballToJson(const BallState& ball);

/// One event: "ball" {t, type, a, b, va, vb}, "cushion" {t, type, ball, v},
/// "pocket" {t, type, ball, pocket}, "rest" {t, type}.
nlohmann::ordered_json eventToJson(const Event& event);

}  // namespace nineball::io
