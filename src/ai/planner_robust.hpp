#pragma once

#include <cstddef>
#include <vector>

#include "ai/planner_evaluate.hpp"
#include "nineball/planner.hpp"

namespace nineball::ai {

/// The robustness check's verdict: which candidate, turned by how much, and its worth.
struct RobustChoice {
  std::size_t index = 0;   ///< into the candidates
  double aim_shift = 0.0;  ///< rad added to the candidate's heading
  double value = 0.0;      ///< expected worth under the level's cueing errors
  long simulations = 0;
};

/// Re-simulates the candidates at `ranked` (best first) on a grid of heading errors (steps of
/// half the check's aim deviation, out to +-robust_steps) times speed errors (-1, 0, +1
/// deviations), and returns the candidate and heading shift (up to one deviation either way,
/// to centre the aim in the window that works) with the best expected worth, weighting the
/// grid as the errors' normal distribution would. Ties go to the better-ranked candidate and
/// the smaller shift, so the answer never depends on the threads. `error_scale` scales the
/// check's deviations (the break is cued more precisely); `centre` false keeps the aim as is.
/// `position_gain[i]` (when not empty) is what a look one shot further ahead added to
/// candidate i's worth when it keeps the table; it is added to every grid point that does.
/// A speed error in m/s (LevelSettings::speed_noise_ms, the tournaments') is the cue stick's:
/// it reaches the ball as ballSpeedPerStickSpeed of the candidate's tip says (`ball_mass`, kg).
RobustChoice chooseRobustly(const std::vector<Candidate>& cands,
                            const std::vector<std::size_t>& ranked, const Evaluator& eval,
                            const LevelSettings& level, double ball_mass, int threads,
                            double error_scale, bool centre,
                            const std::vector<double>& position_gain = {});

/// The cue ball's speed per m/s of the cue stick's, as the tournaments' simulator (FastFiz)
/// strikes with a `tip` offset (fractions of R) and its 600 g cue.
double ballSpeedPerStickSpeed(Vec2 tip, double ball_mass);

}  // namespace nineball::ai
