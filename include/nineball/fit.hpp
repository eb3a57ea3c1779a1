#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "nineball/params.hpp"
#include "nineball/sim.hpp"
#include "nineball/table.hpp"

/// Recorded shots from a real table, the shot that best reproduces each one, and physics
/// calibrated to many of them (docs/calibrating.md).
namespace nineball {

/// One ball's tracked path: positions (m, from the table centre) at the recording's own times
/// (s, increasing; its t = 0 need not be the strike).
struct RecordedPath {
  std::string name;
  std::vector<double> t, x, y;
};

/// A recorded shot: every tracked ball, on a table with its physics.
struct Recording {
  std::string id;
  /// The id came as a JSON integer (its digits in `id`): printed back as one.
  bool integer_id = false;
  TableDef table;
  PhysicsParams physics;
  std::vector<RecordedPath> balls;
  /// The struck ball's name; empty: the ball that moves first.
  std::string cue_ball;
};

/// Empty when the recording can be fitted, else a message naming what is wrong
/// ("balls.white.t: decreasing at sample 12", "balls.white: samples 0-1 imply 6e+196 m/s").
/// A time may repeat (a coarse clock); no pair of samples may imply more than a cue gives.
std::optional<std::string> recordingFault(const Recording& r);

/// How a tracker sees a table: its frame rate, its noise, and when on its clock the shot
/// was struck.
struct Tracker {
  double hz = 50.0;        ///< frames per second
  double noise = 0.005;    ///< m, Gaussian, on each coordinate
  double strike = 0.5;     ///< s, the recording's time of the strike
  std::uint64_t seed = 1;  ///< of the noise
};

/// A recording of a checked scene (with a shot) as `tracker` would make it: every ball at
/// every frame from 0 to the end of the run, read off the run exactly, with noise added and
/// each position clamped at the cushion lines (no tracker sees a centre nearer a cushion than
/// R). names[i] names scene ball i. For tests and for trying the workflow.
Recording recordScene(const Scene& scene, const std::vector<std::string>& names,
                      const Tracker& tracker, const std::string& id = "synthetic");

/// What a fit minimises.
enum class FitObjective {
  Full,   ///< RMSE over every recorded sample of every ball
  Early,  ///< t <= 4 s after the strike, the cue ball weighted 1.5, each sample by 1/(1 + t)
};

/// The errors of a fitted shot against its recording (m).
struct FitErrors {
  double full = 0.0;
  double early = 0.0;
};

/// The shot that best reproduces a recording.
struct ShotFit {
  std::string id;
  /// A complete scene (the reference engine): the balls where the recording has them at the
  /// strike, the fitted shot; simulated, it gives the fit.
  Scene scene;
  /// names[i]: the recorded ball scene ball i (id i) stands for; the cue ball is id 0.
  std::vector<std::string> names;
  /// The recording's time of the strike (simulated time 0).
  double strike_time = 0.0;
  FitErrors rmse;
  /// Simulations the search ran.
  int evals = 0;
  /// Why the fit may mislead, in short phrases ("nothing moves", "did not converge", ...;
  /// docs/calibrating.md); empty when nothing is amiss.
  std::vector<std::string> warnings;
  /// The recorded balls the fitted scene does not reproduce: moving (beyond 2 cm) in the
  /// recording and not in the simulation, or the other way round.
  std::vector<std::string> unreproduced;
};

struct FitOptions {
  int evals = 12000;  ///< simulations per shot (at least kMinFitEvals)
  FitObjective objective = FitObjective::Full;
  std::uint64_t seed = 1;
  int threads = 0;  ///< 0: one per core
  /// Called after each shot with the number done and the total (from any thread, one call at
  /// a time).
  std::function<void(std::size_t, std::size_t)> progress;
  const std::atomic<bool>* cancel = nullptr;
};

constexpr int kMinFitEvals = 50;

/// The errors of `scene` (whose balls stand for `names`) against the recording, struck at the
/// recording's time `strike_time`.
FitErrors fitErrors(const Recording& r, const Scene& scene, const std::vector<std::string>& names,
                    double strike_time);

/// Fits one checked recording (see recordingFault), its warnings and unreproduced balls
/// included (reviewFit). Deterministic for a seed.
ShotFit fitShot(const Recording& r, const FitOptions& options);

/// Sets the warnings and unreproduced balls of `fit`, a fit of the checked recording `r` under
/// `physics`: whether a short search from it (a few % of `evals`) still lowers its error under
/// `objective`, and the fitted scene simulated once against the recording.
void reviewFit(const Recording& r, const PhysicsParams& physics, ShotFit& fit, int evals,
               FitObjective objective, const std::atomic<bool>* cancel = nullptr);

/// Fits every recording, on up to options.threads threads; the results, in order, do not
/// depend on the threads.
std::vector<ShotFit> fitShots(const std::vector<Recording>& shots, const FitOptions& options);

/// The physics with the searched parameters set to `values`, or why they cannot be (a name the
/// physics does not take, a value out of its range): set by the caller, who knows the names.
using PhysicsSetter = std::function<std::optional<PhysicsParams>(
    const PhysicsParams& base, const std::vector<double>& values, std::string& why)>;

struct CalibrateOptions {
  std::vector<std::string> params;  ///< the physics parameters searched, by name
  /// Their values in the recordings' physics (the search starts there).
  std::vector<double> start;
  PhysicsSetter set;
  double holdout = 0.5;  ///< the share of shots kept out of the training, drawn by the seed
  std::uint64_t seed = 1;
  int evals = 6000;       ///< simulations of each shot's first fit
  int refit_evals = 900;  ///< simulations of each shot's refit under each candidate physics
  int candidates = 60;    ///< physics candidates the search tries
  int resamples = 200;    ///< of the training shots, for the standard errors
  int threads = 0;
  /// Called with a line of progress (a stage, a candidate and its median).
  std::function<void(const std::string&)> progress;
  const std::atomic<bool>* cancel = nullptr;
};

/// A physics the calibration scored: a pure function of its values, the shots, the options and
/// the seed (however often, and in whichever round, it is tried).
struct ScoredPhysics {
  std::vector<double> values;  ///< the searched parameters, in options.params' order
  /// m: each training shot's full RMSE refitted under this physics, in Calibration::train's
  /// order; empty for a physics the setter refuses.
  std::vector<double> errors;
  double median = 0.0;  ///< m, of `errors`; infinite for a physics refused
};

/// How far the calibrated values can be trusted: the spread of the calibration's result over
/// resamples of the training shots (a bootstrap), which needs no further simulation.
struct CalibrationUncertainty {
  std::string method = "bootstrap over shots";
  int resamples = 0;
  /// Each parameter's standard error, in options.params' order; empty where it cannot be
  /// determined (`why_not` says why).
  std::vector<std::optional<double>> stderrs;
  /// Rows and columns in options.params' order: ones on the diagonal, empty where either
  /// parameter's standard error is.
  std::vector<std::vector<std::optional<double>>> correlation;
  std::string why_not;  ///< empty when every standard error is determined
};

struct Calibration {
  PhysicsParams physics;
  std::vector<std::string> params;          ///< the parameters' names: options.params
  std::vector<double> values;               ///< the calibrated parameters, in options.params' order
  double train_median = 0.0;                ///< m, the median full RMSE of the training shots
  double holdout_median = 0.0;              ///< m; 0 without held-out shots
  std::vector<std::size_t> train, holdout;  ///< indices into the shots
  /// Every shot refitted under the calibrated physics (its warnings and unreproduced balls
  /// left to reviewFit).
  std::vector<ShotFit> fits;
  CalibrationUncertainty uncertainty;
  /// The search's last round lowered the median by less than 1 %, its simplex closed in (within
  /// its tolerance, or to under half of every standard error), and every standard error is
  /// determined; `convergence` says why, or why not, in a few words.
  bool converged = false;
  std::string convergence;
  /// Every physics the scoring rounds tried (docs/calibrating.md), in the order first tried.
  std::vector<ScoredPhysics> tried;
};

/// Calibrates the physics of checked recordings that share one table and physics.
Calibration calibrate(const std::vector<Recording>& shots, const CalibrateOptions& options);

}  // namespace nineball
