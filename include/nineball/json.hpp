#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "nineball/fit.hpp"
#include "nineball/sim.hpp"

/// The JSON contracts of `nineball sim` (docs/cli.md) for programs that link the library: the
/// scene read exactly as the command reads it, and the result written as it prints it.
namespace nineball {

/// Why a scene was refused: the message the command line prints, naming the field.
struct SceneRefusal {
  std::string message;
};

/// The scene in `text`, or why it is refused (bad JSON, an unknown field, a value out of range,
/// balls that do not fit the table).
std::variant<Scene, SceneRefusal> readScene(std::string_view text);

/// The result document `nineball sim` prints, as compact JSON text (with the trace when the
/// result has one).
std::string resultJsonText(const SimResult& result);

/// The physics preset `name` ("real", "paper") as the scene's "physics" object with every
/// parameter its models read (feeding it back gives the same physics); nothing for another
/// name.
std::optional<std::string> presetJsonText(const std::string& name);

/// The physics `p` as a scene's "physics" object with every parameter its models read, as
/// compact JSON text (feeding it back gives the same physics).
std::string physicsJsonText(const PhysicsParams& p);

/// What `nineball match` prints for the script `text` (docs/cli.md): the rack played, the
/// computer's turns planned, as compact JSON text ("partial": true when a shot stopped with
/// balls still moving). Or why the script, or one of its turns, is refused. A computer's turn
/// the rules refuse is a defect: std::runtime_error.
std::variant<std::string, SceneRefusal> matchJsonText(std::string_view text);

/// What `nineball plan` prints for `text` (the scene plus "game", "rules", "ball_in_hand",
/// "level"; docs/cli.md), as compact JSON text: the shot the computer would play, as
/// intended. Or why the scene is refused.
std::variant<std::string, SceneRefusal> planJsonText(std::string_view text);

/// One line of what `nineball fit` prints: a shot's fit, or its refusal.
struct FitLine {
  /// The line's compact JSON, without its newline: the fit, or {"id", "error"}.
  std::string text;
  /// For a refused shot, the message named by where the shot stands ("line 4: balls.red.t:
  /// decreasing at sample 5"); empty for a fit.
  std::string refusal;
};

/// How `nineball fit` went over a text of shots.
struct FitSummary {
  std::size_t shots = 0;
  std::size_t refused = 0;
  /// options.cancel was raised: only the shots done before it have their lines.
  bool cancelled = false;
};

/// `nineball fit` shot by shot (docs/cli.md): `line` is called with each shot's line in the
/// input's order, as soon as that shot and every one before it are done (a refused shot at
/// once), one call at a time, from any thread. Once options.cancel is raised no fit starts,
/// the fits it cut short have no line, and the lines of every shot done still come, in order.
/// Or why the text holds no shots at all (not JSON, nor JSON Lines; an empty array).
std::variant<FitSummary, SceneRefusal> fitJsonLines(
    std::string_view text, const FitOptions& options,
    const std::function<void(const FitLine&)>& line);

/// What `nineball fit` prints for the recorded shots in `text` (one object, an array, or JSON
/// Lines; docs/cli.md): one JSON line per shot, in order, a refused shot's line its
/// {"id", "error"}. Or why the text holds no shots at all.
std::variant<std::string, SceneRefusal> fitJsonText(std::string_view text,
                                                    const FitOptions& options);

/// What `nineball calibrate` is asked for: the parameters by name and the search's settings.
struct CalibrateRequest {
  std::vector<std::string> params;
  double holdout = 0.5;
  std::uint64_t seed = 1;
  int evals = 6000;
  int refit_evals = 900;
  int candidates = 60;
  int threads = 0;
  std::function<void(const std::string&)> progress;
  const std::atomic<bool>* cancel = nullptr;
};

/// What `nineball calibrate` prints for the recorded shots in `text` (one JSON object). Or why
/// they, or the parameters, are refused.
std::variant<std::string, SceneRefusal> calibrateJsonText(std::string_view text,
                                                          const CalibrateRequest& request);

/// The scene `text` (with a shot) recorded as `tracker` would (recordScene), as a recorded
/// shot's JSON; names[i] names scene ball i. Or why the scene is refused.
std::variant<std::string, SceneRefusal> recordingJsonText(std::string_view scene,
                                                          const std::vector<std::string>& names,
                                                          const Tracker& tracker);

}  // namespace nineball
