#pragma once

#include <atomic>
#include <functional>
#include <vector>

namespace nineball::fit {

/// The least value found and where.
struct Minimum {
  std::vector<double> x;
  double f = 0.0;
  int evals = 0;
  /// The search stopped because its simplex closed in within the tolerance, not because the
  /// budget ran out or it was cancelled.
  bool converged = false;
  /// Along each coordinate, the furthest the simplex's last vertices lie from `x`: how closely
  /// the search has pinned the least down.
  std::vector<double> extent;
};

/// Nelder and Mead's downhill simplex (Computer Journal 7, 1965) with the standard
/// coefficients (reflection 1, expansion 2, contraction 1/2, shrink 1/2): derivative-free, so
/// it needs nothing of a simulation but its error. Starts from `x0` with a first step of
/// `step[i]` along each coordinate; stops after `budget` evaluations, once every vertex lies
/// within `tolerance` x step of the best along every coordinate, or when `cancel` is raised.
Minimum nelderMead(const std::function<double(const std::vector<double>&)>& f,
                   const std::vector<double>& x0, const std::vector<double>& step, int budget,
                   double tolerance = 1e-3, const std::atomic<bool>* cancel = nullptr);

}  // namespace nineball::fit
