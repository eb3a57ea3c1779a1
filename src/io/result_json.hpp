#pragma once

#include <nlohmann/json.hpp>

#include "nineball/sim.hpp"

namespace nineball::io {

/// The result document of `nineball sim` (design.md, "Headless interface"), keys in the
/// design's order: {"time", "steps", "wall_ms", "balls", "events"}.
nlohmann::ordered_json resultToJson(const SimResult& result);

/// {"id", "x", "y", "vx", "vy", "pocket": null | "top-left" | ...}.
nlohmann::ordered_json ballToJson(const BallState& ball);

/// One event: "ball" {t, type, a, b, va, vb}, "cushion" {t, type, ball, v},
/// "pocket" {t, type, ball, pocket}, "rest" {t, type}.
nlohmann::ordered_json eventToJson(const Event& event);

}  // namespace nineball::io
