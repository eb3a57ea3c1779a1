#pragma once

#include <memory>
#include <vector>

#include "audio/impact.hpp"
#include "nineball/match.hpp"
#include "window/fixed_step_clock.hpp"
#include "window/shot_steps.hpp"

namespace nineball::window {

/// The last shot of a rack played again from the physics, not from recorded frames: the rack
/// is rebuilt from its setup and the turns before the shot, which the simulation repeats bit
/// for bit, and the shot is then stepped for the window at normal speed or slowed. No SFML.
class ShotReplay {
 public:
  /// `turns` are every turn of the rack so far; the last shot (or push-out) among them is
  /// replayed, the turns before it are played at once. `rate` is play time per real second.
  ShotReplay(const MatchSetup& rack_setup, const std::vector<TurnInput>& turns, double rate);
  ~ShotReplay();

  /// True when the rack has a shot to replay.
  static bool available(const std::vector<TurnInput>& turns);

  /// Runs the replay for one frame's real time; returns the sounds it made.
  std::vector<audio::Impact> advance(double seconds);
  /// True once every ball rests again.
  bool finished() const { return finished_; }
  /// The balls where the frame should draw them, between the last two steps.
  std::vector<BallState> balls() const;
  /// The replayed world's time at those balls (s).
  double time() const;
  double rate() const { return rate_; }

 private:
  std::unique_ptr<Match> match_;
  double rate_;
  FixedStepClock clock_;
  ShotSteps steps_;
  bool finished_ = false;
};

}  // namespace nineball::window
