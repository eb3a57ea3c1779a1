#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string_view>
#include <variant>

#include "io/parse_error.hpp"
#include "nineball/sim.hpp"

namespace nineball::io {

/// A scene ready for simulate(), or why it was refused.
using SceneResult = std::variant<Scene, ParseError>;

/// Parses the scene document of `nineball sim` (design.md, "Headless interface"), then checks
/// it with validateScene. Every refusal names the field: "balls[2].x: expected a number, ...".
SceneResult parseScene(std::string_view text);

/// The same for a document already parsed.
SceneResult sceneFromJson(const nlohmann::json& doc);

}  // namespace nineball::io
