#include "app/fit_command.hpp"

#include <chrono>
#include <functional>
#include <istream>
#include <ostream>
#include <sstream>

#include "app/cli_checks.hpp"
#include "app/exit_codes.hpp"
#include "app/read_input.hpp"
#include "nineball/json.hpp"

namespace nineball::app {
namespace {

using Clock = std::chrono::steady_clock;

// A line on stderr at most once a second, and at the end, for runs long enough to wait on.
class Progress {
 public:
  Progress(std::ostream& err, std::string what) : err_(err), what_(std::move(what)) {}

  void operator()(std::size_t done, std::size_t total) {
    const auto now = Clock::now();
    if (done < total && now - last_ < std::chrono::seconds(1)) return;
    last_ = now;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    err_ << what_ << done << " of " << total << " shots fitted (" << static_cast<int>(seconds)
         << " s)\n"
         << std::flush;
  }

 private:
  std::ostream& err_;
  std::string what_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_ = Clock::now();
};

std::vector<std::string> splitNames(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) names.push_back(name);
  return names;
}

}  // namespace

CLI::App* addFitCommand(CLI::App& app, FitCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "fit", "Find the shot that best reproduces each recorded shot (JSON or JSON Lines)");
  cmd->add_option("file", options.path, "Recorded shots, or - to read standard input")->required();
  cmd->add_option("--evals", options.evals, "Simulations per shot")
      ->check(CLI::Range(kMinFitEvals, 1000000))
      ->capture_default_str();
  cmd->add_option("--objective", options.objective,
                  "What the fit minimises: full (every sample) or early (4 s after the strike)")
      ->check(CLI::IsMember({"full", "early"}))
      ->capture_default_str();
  cmd->add_option("--seed", options.seed, "Seed of the search's restarts")
      ->check(seedCheck())
      ->capture_default_str();
  cmd->add_option("--threads", options.threads, "Threads (0: one per core)")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  return cmd;
}

CLI::App* addCalibrateCommand(CLI::App& app, CalibrateCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand("calibrate",
                                     "Calibrate physics parameters to recorded shots of one table");
  cmd->add_option("file", options.path, "Recorded shots, or - to read standard input")->required();
  cmd->add_option("--params", options.params,
                  "Physics parameters to calibrate, comma-separated (rolling_friction,...)")
      ->required();
  cmd->add_option("--holdout", options.settings.holdout, "Share of the shots kept out of the training")
      ->check(CLI::Range(0.0, 0.9))
      ->capture_default_str();
  cmd->add_option("--seed", options.settings.seed, "Seed of the held-out draw and the searches")
      ->check(seedCheck())
      ->capture_default_str();
  cmd->add_option("--evals", options.settings.evals, "Simulations of each shot's first fit")
      ->check(CLI::Range(kMinFitEvals, 1000000))
      ->capture_default_str();
  cmd->add_option("--refit-evals", options.settings.refit_evals,
                  "Simulations of each training shot's refit under each candidate physics")
      ->check(CLI::Range(10, 100000))
      ->capture_default_str();
  cmd->add_option("--candidates", options.settings.candidates, "Physics candidates the search tries")
      ->check(CLI::Range(2, 10000))
      ->capture_default_str();
  cmd->add_option("--threads", options.settings.threads, "Threads (0: one per core)")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  return cmd;
}

// Reads the shots' text and prints what `answer` makes of it: the JSON on `out`, or a refusal
// on `err` (kExitBadInput).
static int answerShots(const std::string& command, const std::string& path, std::istream& in,
                std::ostream& out, std::ostream& err,
                const std::function<std::variant<std::string, SceneRefusal>(std::string_view)>&
                    answer) {
  const std::string prefix = "nineball " + command + ": " + shownPath(path) + ": ";
  std::string why;
  const auto text = readInput(path, in, why, limits::kMaxRecordingBytes);
  if (!text) {
    err << prefix << why << '\n';
    return kExitBadInput;
  }
  const auto answered = answer(*text);
  if (const auto* refused = std::get_if<SceneRefusal>(&answered)) {
    err << prefix << refused->message << '\n';
    return kExitBadInput;
  }
  out << std::get<std::string>(answered) << std::flush;
  return out ? kExitOk : kExitInternal;
}

int runFit(const FitCommandOptions& options, std::istream& in, std::ostream& out,
           std::ostream& err) {
  FitOptions o;
  o.evals = options.evals;
  o.objective = options.objective == "early" ? FitObjective::Early : FitObjective::Full;
  o.seed = options.seed;
  o.threads = options.threads;
  Progress progress(err, "nineball fit: ");
  o.progress = [&](std::size_t done, std::size_t total) {
    if (total > 1) progress(done, total);
  };
  return answerShots("fit", options.path, in, out, err,
                     [&](std::string_view text) { return fitJsonText(text, o); });
}

int runCalibrate(const CalibrateCommandOptions& options, std::istream& in, std::ostream& out,
                 std::ostream& err) {
  CalibrateRequest r = options.settings;
  r.params = splitNames(options.params);
  r.progress = [&](const std::string& line) {
    err << "nineball calibrate: " << line << '\n' << std::flush;
  };
  return answerShots("calibrate", options.path, in, out, err,
                     [&](std::string_view text) { return calibrateJsonText(text, r); });
}

}  // namespace nineball::app
