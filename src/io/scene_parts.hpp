#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/params.hpp"
#include "nineball/shot.hpp"
#include "nineball/table.hpp"

// The parts of a scene document that other documents (the match script, the planner's
// scene) share. Each throws ParseError naming the field.
namespace nineball::io {

/// "9ft" | "8ft" | "7ft" | {"length", "width", ...} at "table".
TableDef parseTable(const nlohmann::json& v);
/// {"preset", overrides...} at "physics".
PhysicsParams parsePhysics(const nlohmann::json& v);
/// The physics object that parsePhysics reads back as `p`: the models by name and every
/// parameter they read.
nlohmann::ordered_json physicsToJson(const PhysicsParams& p);
/// [{"id", "x", "y", "vx", "vy", "mass"}, ...] at "balls".
/// Balls of the given radius (it bounds their spin).
std::vector<BallState> parseBalls(const nlohmann::json& v, const PhysicsParams& physics);
/// {"hz", "velocity_iterations", ...} at "step".
StepParams parseStep(const nlohmann::json& v);
/// [side, height] at `path`.
Vec2 parseTip(const nlohmann::json& v, const std::string& path);
/// The shot members of the object `v` ("heading_deg", "speed" or "force" + "contact_time",
/// "tip"), named under `path`; other members are the caller's to allow or refuse.
Shot parseShotFields(const nlohmann::json& v, const std::string& path, double cue_mass);

}  // namespace nineball::io
