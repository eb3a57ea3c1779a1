#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "nineball/sim.hpp"

namespace nineball::io {

/// The result document of `nineball sim` (design.md, "Headless interface"), keys in the
/// design's order: {"time", "steps", "wall_ms", "end", "partial", "balls", "events"}, then
/// {"trace", "trace_truncated"} when the scene asked for a trace.
nlohmann::ordered_json resultToJson(const SimResult& result);

/// Writes the result document (resultToJson's, the same keys and values) to `out`, indented by
/// 2 or compact on one line. The trace, when there is one, is written array by array on its
/// own lines and never built as one document: at its bound of 1,000,000 samples it is about
/// 100-150 MB of text, which built whole took over 800 MB of memory.
void writeResult(std::ostream& out, const SimResult& result, bool indented);

/// {"<id>": {"t": [...], "x", "y", "vx", "vy", "w": [[wx, wy, wz], ...], "phase": [...]}, ...}.
nlohmann::ordered_json traceToJson(const Trace& trace);

/// {"id", "x", "y", "vx", "vy", "pocket": null | "top-left" | ...}.
nlohmann::ordered_json ballToJson(const BallState& ball);

/// One event: "ball" {t, type, a, b, va, vb}, "cushion" {t, type, ball, v},
/// "pocket" {t, type, ball, pocket}, "rest" {t, type}.
nlohmann::ordered_json eventToJson(const Event& event);

}  // namespace nineball::io
