#include <set>
#include <sstream>

#include "common/limits.hpp"
#include "io/recording_json.hpp"
#include "io/scene_json.hpp"
#include "io/scene_parts.hpp"
#include "nineball/json.hpp"

// The public JSON contracts of `nineball fit` and `nineball calibrate` (include/nineball/json.hpp),
// shared by the command line and the Python package.
namespace nineball {
namespace {

using Shots = std::vector<Recording>;

std::variant<Shots, SceneRefusal> shotsIn(std::string_view text) {
  if (text.size() > limits::kMaxRecordingBytes) {
    return SceneRefusal{"larger than " + std::to_string(limits::kMaxRecordingBytes >> 20) + " MiB"};
  }
  auto parsed = io::parseRecordings(text);
  if (const auto* refused = std::get_if<io::ParseError>(&parsed)) {
    return SceneRefusal{refused->message};
  }
  return std::get<Shots>(std::move(parsed));
}

std::optional<std::string> paramsFault(const std::vector<std::string>& names) {
  if (names.empty()) return std::string("--params: name at least one physics parameter");
  std::set<std::string> seen;
  for (const std::string& n : names) {
    if (n.empty()) return std::string("--params: an empty name");
    if (!seen.insert(n).second) return "--params: \"" + n + "\" named twice";
  }
  return std::nullopt;
}

std::optional<std::string> physicsFault(const Shots& shots) {
  const std::string first = io::physicsToJson(shots.front().physics).dump();
  for (std::size_t i = 1; i < shots.size(); ++i) {
    if (io::physicsToJson(shots[i].physics).dump() != first) {
      return "shot " + std::to_string(i + 1) +
             ": physics differs from the first shot's: calibrate one table's shots at a time";
    }
  }
  return std::nullopt;
}

}  // namespace

std::variant<std::string, SceneRefusal> fitJsonText(std::string_view text,
                                                    const FitOptions& options) {
  auto shots = shotsIn(text);
  if (auto* refused = std::get_if<SceneRefusal>(&shots)) return *refused;
  std::string out;
  for (const ShotFit& f : fitShots(std::get<Shots>(shots), options)) {
    out += io::fitToJson(f).dump() + "\n";
  }
  return out;
}

std::variant<std::string, SceneRefusal> calibrateJsonText(std::string_view text,
                                                          const CalibrateRequest& request) {
  if (auto fault = paramsFault(request.params)) return SceneRefusal{*fault};
  if (!(request.holdout >= 0.0 && request.holdout <= 0.9)) {
    return SceneRefusal{"--holdout: must be from 0 to 0.9"};
  }
  auto read = shotsIn(text);
  if (auto* refused = std::get_if<SceneRefusal>(&read)) return *refused;
  const Shots& shots = std::get<Shots>(read);
  if (auto fault = physicsFault(shots)) return SceneRefusal{*fault};
  auto start = io::physicsValues(shots.front().physics, request.params);
  if (const auto* refused = std::get_if<io::ParseError>(&start)) {
    return SceneRefusal{refused->message};
  }
  CalibrateOptions o;
  o.params = request.params;
  o.start = std::get<std::vector<double>>(start);
  o.set = io::physicsSetter(request.params);
  o.holdout = request.holdout;
  o.seed = request.seed;
  o.evals = std::max(request.evals, kMinFitEvals);
  o.refit_evals = std::max(request.refit_evals, 10);
  o.candidates = std::max(request.candidates, 2);
  o.threads = request.threads;
  o.progress = request.progress;
  o.cancel = request.cancel;
  return io::calibrationToJson(calibrate(shots, o), shots).dump(2) + "\n";
}

std::variant<std::string, SceneRefusal> recordingJsonText(std::string_view scene,
                                                          const std::vector<std::string>& names,
                                                          const Tracker& tracker) {
  auto parsed = io::parseScene(scene);
  if (const auto* refused = std::get_if<io::ParseError>(&parsed)) {
    return SceneRefusal{refused->message};
  }
  const Scene& s = std::get<Scene>(parsed);
  if (!s.shot) return SceneRefusal{"shot: a recording needs a shot to record"};
  if (names.size() != s.balls.size()) {
    return SceneRefusal{"names: " + std::to_string(names.size()) + " names for " +
                        std::to_string(s.balls.size()) + " balls"};
  }
  if (!(tracker.hz > 0.0 && tracker.hz <= limits::kMaxTraceHz) ||
      !(tracker.noise >= 0.0 && tracker.noise <= 1.0) ||
      !(tracker.strike >= 0.0 && tracker.strike <= 60.0)) {
    return SceneRefusal{"tracker: hz in (0, 10000], noise in [0, 1] m, strike in [0, 60] s"};
  }
  Recording r = recordScene(s, names, tracker, "synthetic");
  if (auto fault = recordingFault(r)) return SceneRefusal{*fault};
  return io::recordingToJson(r).dump() + "\n";
}

}  // namespace nineball
