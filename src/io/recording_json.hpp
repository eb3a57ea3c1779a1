#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "io/parse_error.hpp"
#include "nineball/fit.hpp"

// The documents of `nineball fit` and `nineball calibrate` (docs/cli.md): recorded shots in,
// fitted shots and calibrated physics out.
namespace nineball::io {

/// One shot of a text of recorded shots: read and checked, or refused by itself.
struct ShotInput {
  /// Where it stands: "shot 3" (of an array), "line 4" (of JSON Lines), "" (a lone object).
  std::string where;
  /// The shot, read and checked (recordingFault); nothing when it is refused.
  std::optional<Recording> recording;
  /// Why it is refused, naming the field ("balls.red.t: decreasing at sample 5").
  std::string refusal;
  /// Its id as given (a string or an integer), else null: a refusal's line carries it.
  nlohmann::ordered_json id;

  /// The refusal named by where the shot stands: "shot 3: balls.red.t: ...".
  std::string namedRefusal() const;
};

/// Recorded shots: one JSON object, an array of them, or JSON Lines (one object a line), each
/// read and checked by itself. Refused whole (a ParseError) only when the text holds no shots:
/// not JSON (nor JSON Lines), an empty array, a document neither an object nor an array.
std::variant<std::vector<ShotInput>, ParseError> readRecordings(std::string_view text);

/// The shots of readRecordings all read, or the first refusal, named by where the shot stands
/// ("shot 3: balls.red.t: ...").
std::variant<std::vector<Recording>, ParseError> parseRecordings(std::string_view text);

/// One recorded shot from its object.
Recording recordingFromJson(const nlohmann::json& v);

/// A recorded shot as parseRecordings reads it.
nlohmann::ordered_json recordingToJson(const Recording& r);

/// A scene as `nineball sim` reads it: table, physics, balls, shot, step.
nlohmann::ordered_json sceneToJson(const Scene& scene);

/// A fitted shot of the recording `shot`: {"id" (as the recording gave it), "scene", "names",
/// "strike_time", "rmse_m": {"full", "early"}, "evals", "warnings", "unreproduced"}.
nlohmann::ordered_json fitToJson(const ShotFit& fit, const Recording& shot);

/// A refused shot's line: {"id" (only when it had one), "error"}.
nlohmann::ordered_json refusalToJson(const ShotInput& shot);

/// {"physics", "parameters": {name: {"value", "stderr"}}, "uncertainty": {"method",
/// "resamples"}, "correlation": [[...]], "converged", "convergence", "train": {"median_rmse_m",
/// "shots", "unreproduced_balls"}, "holdout": {...}, "per_shot": [...]}.
nlohmann::ordered_json calibrationToJson(const Calibration& c, const std::vector<Recording>& shots);

/// Sets the named physics parameters as a scene's "physics" object would ("rolling_friction",
/// "ball_friction.a"), checked as a scene checks them.
PhysicsSetter physicsSetter(const std::vector<std::string>& names);

/// The named parameters' values in `p`, or why one cannot be calibrated (a name the scene's
/// physics does not take, or one its models do not read).
std::variant<std::vector<double>, ParseError> physicsValues(const PhysicsParams& p,
                                                            const std::vector<std::string>& names);

}  // namespace nineball::io
