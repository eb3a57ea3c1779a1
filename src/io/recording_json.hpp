#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "io/parse_error.hpp"
#include "nineball/fit.hpp"

// The documents of `nineball fit` and `nineball calibrate` (docs/cli.md): recorded shots in,
// fitted shots and calibrated physics out.
namespace nineball::io {

/// Recorded shots: one JSON object, an array of them, or JSON Lines (one object a line). Each
/// is checked (recordingFault); a refusal names the shot ("shot 3: balls.red.t: ...").
std::variant<std::vector<Recording>, ParseError> parseRecordings(std::string_view text);

/// One recorded shot from its object.
Recording recordingFromJson(const nlohmann::json& v);

/// A recorded shot as parseRecordings reads it.
nlohmann::ordered_json recordingToJson(const Recording& r);

/// A scene as `nineball sim` reads it: table, physics, balls, shot, step.
nlohmann::ordered_json sceneToJson(const Scene& scene);

/// A fitted shot: {"id", "scene", "names", "strike_time", "rmse_m": {"full", "early"},
/// "evals"}.
nlohmann::ordered_json fitToJson(const ShotFit& fit);

/// {"physics", "parameters": {name: {"value", "stderr"}}, "uncertainty": {"method",
/// "resamples"}, "correlation": [[...]], "converged", "convergence", "train": {"median_rmse_m",
/// "shots"}, "holdout": {...}, "per_shot": [...]}.
nlohmann::ordered_json calibrationToJson(const Calibration& c, const std::vector<Recording>& shots);

/// Sets the named physics parameters as a scene's "physics" object would ("rolling_friction",
/// "ball_friction.a"), checked as a scene checks them.
PhysicsSetter physicsSetter(const std::vector<std::string>& names);

/// The named parameters' values in `p`, or why one cannot be calibrated (a name the scene's
/// physics does not take, or one its models do not read).
std::variant<std::vector<double>, ParseError> physicsValues(const PhysicsParams& p,
                                                            const std::vector<std::string>& names);

}  // namespace nineball::io
