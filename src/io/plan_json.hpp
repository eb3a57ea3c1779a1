#pragma once

#include <nlohmann/json.hpp>
#include <string_view>
#include <variant>

#include "io/parse_error.hpp"
#include "nineball/planner.hpp"

namespace nineball::io {

/// The position of `nineball plan`: the scene and the rules' state, and the level to plan at.
struct PlanScene {
  ai::PlanInput input;
  ai::Level level = ai::Level::Master;
};

using PlanSceneResult = std::variant<PlanScene, ParseError>;

/// Parses the scene document of `nineball sim` plus optional "rules" ("wpa" | "paper"),
/// "ball_in_hand" (true: the cue ball is placed first, and may be left out of "balls") and
/// "level" (a level's name, ai::levelNames, default master). A "shot" or "until" is checked as in
/// a sim scene and otherwise ignored. The ball on is the lowest-numbered object ball. Every
/// refusal names the field.
PlanSceneResult parsePlanScene(std::string_view text);

/// A heading in radians as degrees in (-180, 180], the way shots read best.
double headingDegrees(double rad);

/// {"heading_deg", "speed", "tip": [side, height]}, the scene format's shot object, plus
/// "cue": [x, y] when the plan places the cue ball.
nlohmann::ordered_json planToJson(const ai::Plan& plan);

}  // namespace nineball::io
