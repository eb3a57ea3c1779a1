#pragma once

#include <algorithm>
#include <cmath>

namespace nineball::window {

/// Turns frame times into fixed physics steps: an accumulator with a cap on catch-up steps
/// (a slow frame slows the game down instead of freezing it), and the fraction of a step
/// left over for drawing between the last two states.
class FixedStepClock {
 public:
  FixedStepClock(double dt, int max_steps_per_frame) : dt_(dt), max_steps_(max_steps_per_frame) {}

  /// The clock the window plays a match's steps (`hz` a second) on: one frame catches up at
  /// most a quarter of a second of play; past it a slow frame slows the game down.
  static FixedStepClock forPlay(double dt, double hz) {
    constexpr double kMaxCatchUp = 0.25;
    return FixedStepClock(dt, std::max(1, static_cast<int>(std::ceil(kMaxCatchUp * hz))));
  }

  /// Adds one frame's time and says how many steps to take now.
  int advance(double seconds) {
    acc_ += std::max(0.0, seconds);
    int steps = static_cast<int>(acc_ / dt_);
    if (steps > max_steps_) {
      steps = max_steps_;
      acc_ = 0.0;  // what could not be caught up is dropped, not carried
    } else {
      acc_ -= steps * dt_;
    }
    return steps;
  }

  /// How far past the last step the frame is, 0 to 1: the interpolation weight of the
  /// newest state against the one before it.
  double alpha() const { return std::clamp(acc_ / dt_, 0.0, 1.0); }

  void reset() { acc_ = 0.0; }
  double dt() const { return dt_; }

 private:
  double dt_;
  int max_steps_;
  double acc_ = 0.0;
};

}  // namespace nineball::window
