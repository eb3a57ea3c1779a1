#include "ai/planner_robust.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "common/parallel_map.hpp"

namespace nineball::ai {
namespace {

// Grid steps per standard deviation of the aim error.
constexpr double kStepsPerDeviation = 2.0;
// Speed errors tried, in deviations, and their weights (a three-point normal rule).
constexpr double kSpeedErrors[] = {-1.0, 0.0, 1.0};
constexpr double kSpeedWeights[] = {0.25, 0.5, 0.25};
constexpr int kSpeedCount = 3;
// The aim may be shifted by up to this many grid steps to centre it.
constexpr int kMaxShiftSteps = 2;

}  // namespace

RobustChoice chooseRobustly(const std::vector<Candidate>& cands,
                            const std::vector<std::size_t>& ranked, const Evaluator& eval,
                            const LevelSettings& level, double ball_mass, int threads,
                            double error_scale, bool centre,
                            const std::vector<double>& position_gain) {
  const int m = level.robust_steps;
  const int aims = 2 * m + 1;
  const std::size_t per = static_cast<std::size_t>(aims * kSpeedCount);
  const double step = error_scale * degToRad(level.robust_aim_deg) / kStepsPerDeviation;
  const double speed_error = error_scale * level.robust_speed;
  std::vector<double> grid(ranked.size() * per, 0.0);
  parallelFor(grid.size(), threads, [&](std::size_t j) {
    const Candidate& c = cands[ranked[j / per]];
    const int a = static_cast<int>(j % per) / kSpeedCount - m;
    const int s = static_cast<int>(j % per) % kSpeedCount;
    Shot shot = c.shot;
    shot.heading_rad += a * step;
    if (level.speed_noise_ms > 0.0) {
      // A speed error in m/s (the tournaments' noise, on the cue stick) weighs most on the
      // softest strokes.
      const double on_ball = ballSpeedPerStickSpeed(c.shot.tip, ball_mass) * level.speed_noise_ms;
      const double sd = std::hypot(speed_error * c.shot.speed, error_scale * on_ball);
      shot.speed = std::max(0.0, c.shot.speed + kSpeedErrors[s] * sd);
    } else {
      shot.speed *= 1.0 + kSpeedErrors[s] * speed_error;
    }
    grid[j] = eval.value(c, shot);
  });

  RobustChoice best;
  best.simulations = static_cast<long>(grid.size());
  best.value = -1.0;
  const int max_shift = centre ? std::min(kMaxShiftSteps, m) : 0;
  for (std::size_t r = 0; r < ranked.size(); ++r) {
    for (int mag = 0; mag <= max_shift; ++mag) {
      for (int shift : {mag, -mag}) {
        double num = 0.0, den = 0.0, kept = 0.0;
        for (int a = -m; a <= m; ++a) {
          const double d = (a - shift) / kStepsPerDeviation;
          const double wa = std::exp(-0.5 * d * d);
          for (int s = 0; s < kSpeedCount; ++s) {
            const double w = wa * kSpeedWeights[s];
            const double v = grid[r * per + static_cast<std::size_t>((a + m) * kSpeedCount + s)];
            num += w * v;
            den += w;
            if (v >= kContinueBase && v < 1.0) kept += w;
          }
        }
        // The look ahead judged the position the shot leaves when it keeps the table: its
        // gain counts as often as the table is kept.
        const double gain = position_gain.empty() ? 0.0 : position_gain[ranked[r]];
        const double expected = (num + gain * kept) / den;
        if (expected > best.value) {
          best.value = expected;
          best.index = ranked[r];
          best.aim_shift = shift * step;
        }
        if (mag == 0) break;
      }
    }
  }
  return best;
}

}  // namespace nineball::ai
