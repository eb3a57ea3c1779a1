#include <algorithm>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>

#include "common/limits.hpp"
#include "common/parallel_map.hpp"
#include "io/recording_json.hpp"
#include "io/scene_json.hpp"
#include "io/scene_parts.hpp"
#include "nineball/json.hpp"

// The public JSON contracts of `nineball fit` and `nineball calibrate` (include/nineball/json.hpp),
// shared by the command line and the Python package.
namespace nineball {
namespace {

using Shots = std::vector<Recording>;
using Inputs = std::vector<io::ShotInput>;

std::optional<SceneRefusal> sizeFault(std::string_view text) {
  if (text.size() <= limits::kMaxRecordingBytes) return std::nullopt;
  return SceneRefusal{"larger than " + std::to_string(limits::kMaxRecordingBytes >> 20) + " MiB"};
}

std::variant<Inputs, SceneRefusal> inputsIn(std::string_view text) {
  if (auto fault = sizeFault(text)) return *fault;
  auto read = io::readRecordings(text);
  if (const auto* refused = std::get_if<io::ParseError>(&read)) {
    return SceneRefusal{refused->message};
  }
  return std::get<Inputs>(std::move(read));
}

// Every shot read, or the first refused, named by where it stands.
std::variant<Shots, SceneRefusal> shotsIn(std::string_view text) {
  if (auto fault = sizeFault(text)) return *fault;
  auto parsed = io::parseRecordings(text);
  if (const auto* refused = std::get_if<io::ParseError>(&parsed)) {
    return SceneRefusal{refused->message};
  }
  return std::get<Shots>(std::move(parsed));
}

bool raised(const std::atomic<bool>* flag) {
  return flag && flag->load();
}

// Each shot's line handed on in the input's order, as soon as it and every line before it
// are done: a file of many shots shows its first fits while the rest are searched.
class InOrder {
 public:
  InOrder(std::size_t count, const std::function<void(const FitLine&)>& hand_on)
      : lines_(count), hand_on_(hand_on) {}

  void done(std::size_t i, FitLine line) {
    const std::lock_guard<std::mutex> lock(mutex_);
    lines_[i] = std::move(line);
    while (next_ < lines_.size() && lines_[next_]) handOn(next_++);
  }

  // After a cancel: the lines of every shot done, past those that never will be.
  void handOnTheRest() {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (; next_ < lines_.size(); ++next_) {
      if (lines_[next_]) handOn(next_);
    }
  }

 private:
  void handOn(std::size_t i) {
    hand_on_(*lines_[i]);
    lines_[i].reset();
  }

  std::mutex mutex_;
  std::vector<std::optional<FitLine>> lines_;
  std::size_t next_ = 0;
  const std::function<void(const FitLine&)>& hand_on_;
};

FitLine refusedLine(const io::ShotInput& in) {
  return {io::refusalToJson(in).dump(), in.namedRefusal()};
}

std::size_t refusedIn(const Inputs& inputs) {
  return static_cast<std::size_t>(std::count_if(
      inputs.begin(), inputs.end(), [](const io::ShotInput& in) { return !in.recording; }));
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

std::variant<FitSummary, SceneRefusal> fitJsonLines(
    std::string_view text, const FitOptions& options,
    const std::function<void(const FitLine&)>& line) {
  auto read = inputsIn(text);
  if (auto* refused = std::get_if<SceneRefusal>(&read)) return *refused;
  const Inputs& inputs = std::get<Inputs>(read);
  FitSummary summary;
  summary.shots = inputs.size();
  summary.refused = refusedIn(inputs);
  InOrder order(inputs.size(), line);
  std::mutex reporting;
  std::size_t fitted = 0;
  parallelFor(inputs.size(), threadsFor(options.threads), [&](std::size_t i) {
    const io::ShotInput& in = inputs[i];
    if (!in.recording) {
      order.done(i, refusedLine(in));
      return;
    }
    if (raised(options.cancel)) return;
    const ShotFit f = fitShot(*in.recording, options);
    // A fit the cancel cut short is no fit of the shot.
    if (raised(options.cancel)) return;
    order.done(i, {io::fitToJson(f, *in.recording).dump(), ""});
    if (!options.progress) return;
    const std::lock_guard<std::mutex> lock(reporting);
    options.progress(++fitted, summary.shots - summary.refused);
  });
  summary.cancelled = raised(options.cancel);
  if (summary.cancelled) order.handOnTheRest();
  return summary;
}

std::variant<std::string, SceneRefusal> fitJsonText(std::string_view text,
                                                    const FitOptions& options) {
  std::string out;
  const auto run =
      fitJsonLines(text, options, [&](const FitLine& line) { out += line.text + "\n"; });
  if (const auto* refused = std::get_if<SceneRefusal>(&run)) return *refused;
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
  Calibration c = calibrate(shots, o);
  parallelFor(c.fits.size(), threadsFor(o.threads), [&](std::size_t i) {
    reviewFit(shots[i], c.physics, c.fits[i], o.evals, FitObjective::Full, o.cancel);
  });
  return io::calibrationToJson(c, shots).dump(2) + "\n";
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
