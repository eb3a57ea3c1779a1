#include "app/fit_command.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <istream>
#include <mutex>
#include <new>
#include <optional>
#include <ostream>
#include <sstream>
#include <vector>

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
  cmd->add_option("--holdout", options.settings.holdout,
                  "Share of the shots kept out of the training")
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
  cmd->add_option("--candidates", options.settings.candidates,
                  "Physics candidates the search tries")
      ->check(CLI::Range(2, 10000))
      ->capture_default_str();
  cmd->add_option("--threads", options.settings.threads, "Threads (0: one per core)")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  return cmd;
}

namespace {

// Ctrl-C or a kill stops the search. The handler only raises the flag (about all a handler
// may do) and gives the signal back its default, so that a second one ends the process at
// once.
std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler may only set this");
constexpr int kStopSignals[] = {SIGINT, SIGTERM};

extern "C" void requestFitStop(int sig) {
  stop_requested.store(true);
  std::signal(sig, SIG_DFL);
}

class StopOnSignals {
 public:
  StopOnSignals() {
    stop_requested.store(false);
    for (int sig : kStopSignals) {
      previous_.push_back(std::signal(sig, requestFitStop));
      // A signal ignored at the start (a background job's Ctrl-C) stays ignored.
      if (previous_.back() == SIG_IGN) std::signal(sig, SIG_IGN);
    }
  }
  ~StopOnSignals() {
    std::size_t i = 0;
    for (int sig : kStopSignals) std::signal(sig, previous_[i++]);
  }
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

  const std::atomic<bool>* flag() const { return &stop_requested; }
  bool raised() const { return stop_requested.load(); }

 private:
  std::vector<void (*)(int)> previous_;
};

// Memory held back for the way out of an allocation that fails: given back at the first
// failure, so that what unwinds from it (a destructor that allocates among it) still finds
// some and the failure is reported, not an abort; the next failure throws std::bad_alloc.
class MemoryReserve {
 public:
  MemoryReserve() {
    held_.store(::operator new(kBytes, std::nothrow));
    previous_ = std::set_new_handler(&giveBack);
  }
  ~MemoryReserve() {
    std::set_new_handler(previous_);
    ::operator delete(held_.exchange(nullptr));
  }
  MemoryReserve(const MemoryReserve&) = delete;
  MemoryReserve& operator=(const MemoryReserve&) = delete;

 private:
  static constexpr std::size_t kBytes = 16u << 20;

  static void giveBack() {
    void* held = held_.exchange(nullptr);
    if (!held) throw std::bad_alloc();
    ::operator delete(held);
  }

  static inline std::atomic<void*> held_{nullptr};
  std::new_handler previous_ = nullptr;
};

std::string prefixOf(const std::string& command, const std::string& path) {
  return "nineball " + command + ": " + shownPath(path) + ": ";
}

// How a run of fit ends: interrupted, with refused shots, or whole.
int fitStatus(const FitSummary& run, std::size_t printed, const std::string& prefix,
              std::ostream& out, std::ostream& err) {
  if (run.cancelled) {
    err << prefix << "interrupted: " << printed << " of " << run.shots << " shots printed\n";
    return kExitInterrupted;
  }
  if (run.refused > 0) {
    err << prefix << run.refused << " of " << run.shots << " shots refused\n";
    return kExitBadInput;
  }
  return out ? kExitOk : kExitInternal;
}

// The shots' text, or nothing when it cannot be read (said on `err`).
std::optional<std::string> shotsText(const std::string& path, const std::string& prefix,
                                     std::istream& in, std::ostream& err) {
  std::string why;
  auto text = readInput(path, in, why, limits::kMaxRecordingBytes);
  if (!text) err << prefix << why << '\n';
  return text;
}

FitOptions fitOptionsOf(const FitCommandOptions& options, const StopOnSignals& signals) {
  FitOptions o;
  o.evals = options.evals;
  o.objective = options.objective == "early" ? FitObjective::Early : FitObjective::Full;
  o.seed = options.seed;
  o.threads = options.threads;
  o.cancel = signals.flag();
  return o;
}

int fitAndPrint(const FitCommandOptions& options, const StopOnSignals& signals, std::istream& in,
                std::ostream& out, std::ostream& err) {
  const std::string prefix = prefixOf("fit", options.path);
  const auto text = shotsText(options.path, prefix, in, err);
  if (!text) return kExitBadInput;
  FitOptions o = fitOptionsOf(options, signals);
  // Progress and refusals come from different threads: one line on stderr at a time.
  std::mutex stderr_lines;
  Progress progress(err, "nineball fit: ");
  o.progress = [&](std::size_t done, std::size_t total) {
    const std::lock_guard<std::mutex> lock(stderr_lines);
    if (total > 1) progress(done, total);
  };
  std::size_t printed = 0;
  // Each line out as soon as it is due, so that a failure later loses none of them.
  const auto run = fitJsonLines(*text, o, [&](const FitLine& line) {
    out << line.text << '\n' << std::flush;
    ++printed;
    if (line.refusal.empty()) return;
    const std::lock_guard<std::mutex> lock(stderr_lines);
    err << prefix << line.refusal << '\n' << std::flush;
  });
  if (const auto* refused = std::get_if<SceneRefusal>(&run)) {
    err << prefix << refused->message << '\n';
    return kExitBadInput;
  }
  return fitStatus(std::get<FitSummary>(run), printed, prefix, out, err);
}

int calibrateAndPrint(const CalibrateCommandOptions& options, const StopOnSignals& signals,
                      std::istream& in, std::ostream& out, std::ostream& err) {
  const std::string prefix = prefixOf("calibrate", options.path);
  const auto text = shotsText(options.path, prefix, in, err);
  if (!text) return kExitBadInput;
  CalibrateRequest r = options.settings;
  r.params = splitNames(options.params);
  r.progress = [&](const std::string& line) {
    err << "nineball calibrate: " << line << '\n' << std::flush;
  };
  r.cancel = signals.flag();
  const auto answered = calibrateJsonText(*text, r);
  // Physics searched only partly are no calibration.
  if (signals.raised()) {
    err << prefix << "interrupted: nothing printed\n";
    return kExitInterrupted;
  }
  if (const auto* refused = std::get_if<SceneRefusal>(&answered)) {
    err << prefix << refused->message << '\n';
    return kExitBadInput;
  }
  out << std::get<std::string>(answered) << std::flush;
  return out ? kExitOk : kExitInternal;
}

// Runs a command with Ctrl-C and SIGTERM caught and memory held back, so that running out of
// it ends with a message, not an abort.
template <typename Run>
int stoppableAndMemorySafe(const char* command, std::ostream& err, Run run) {
  const StopOnSignals signals;
  const MemoryReserve reserve;
  try {
    return run(signals);
  } catch (const std::bad_alloc&) {
    err << "nineball " << command << ": out of memory\n";
    return kExitInternal;
  }
}

}  // namespace

int runFit(const FitCommandOptions& options, std::istream& in, std::ostream& out,
           std::ostream& err) {
  return stoppableAndMemorySafe("fit", err, [&](const StopOnSignals& signals) {
    return fitAndPrint(options, signals, in, out, err);
  });
}

int runCalibrate(const CalibrateCommandOptions& options, std::istream& in, std::ostream& out,
                 std::ostream& err) {
  return stoppableAndMemorySafe("calibrate", err, [&](const StopOnSignals& signals) {
    return calibrateAndPrint(options, signals, in, out, err);
  });
}

}  // namespace nineball::app
