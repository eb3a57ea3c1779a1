#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "audio/impact.hpp"
#include "nineball/match.hpp"
#include "window/fixed_step_clock.hpp"
#include "window/shot_replay.hpp"
#include "window/shot_steps.hpp"

namespace nineball::window {

/// The shot on the table as the window plays it: the physics stepped in fixed steps (more of
/// them a frame under fast-forward), the last two states a frame draws between, the cue's
/// strike heard with the shot's first frame, the picture's clock running on a moment after the
/// balls rest, and a replay of the rack's last shot played instead while it runs. Whether a
/// shot is rolling is the session's to say (its phase). No SFML.
class ShotPlayback {
 public:
  explicit ShotPlayback(FixedStepClock clock) : clock_(clock) {}

  /// The balls as they stand between shots (a rack, a turn, a restored state).
  void settle(const Match& match);
  /// The balls as the last step left them.
  const std::vector<BallState>& balls() const { return shot_.current; }
  /// A shot `match` has just begun, struck on ball `ball` at `speed` (m/s).
  void begin(const Match& match, int ball, double speed);
  /// Where the struck ball stood as the shot began: its place among the balls, else `fallback`.
  void strikeFrom(Vec2 fallback);
  Vec2 struckFrom() const { return strike_from_; }
  /// The ball the shot rolling (or the last one) was struck on.
  int shotBall() const { return shot_ball_; }
  /// The world's time when the shot began (s).
  double start() const { return shot_.start; }

  /// One frame of `frame_seconds` (times the play rate): the replay's, else the shot's steps
  /// while `rolling`; its sounds go to `impacts`. True once the shot has run out.
  bool advance(double frame_seconds, bool rolling, Match& match,
               std::vector<audio::Impact>& impacts);
  /// The balls a frame draws while a replay runs or the shot rolls (between two steps).
  std::vector<BallState> ballsToDraw(bool rolling) const;
  /// The clock of that picture (s).
  double drawTime(bool rolling) const;

  /// Fast-forward: the physics runs `rate` times as fast, in the same steps. 1 is normal.
  void setPlayRate(double rate) { play_rate_ = rate; }
  double playRate() const { return play_rate_; }

  void startReplay(std::unique_ptr<ShotReplay> replay) { replay_ = std::move(replay); }
  void stopReplay() { replay_.reset(); }
  bool replaying() const { return replay_ != nullptr; }
  /// The replay running (nullptr: none).
  const ShotReplay* replay() const { return replay_.get(); }

 private:
  FixedStepClock clock_;
  ShotSteps shot_;
  std::unique_ptr<ShotReplay> replay_;
  double play_rate_ = 1.0;
  std::optional<audio::Impact> strike_;  // the cue's strike, heard with the next frame
  Vec2 strike_from_;                     // where the struck ball stood
  int shot_ball_ = kCueBall;             // the ball the rolling shot was struck on
  double after_rest_ = 0.0;              // s the picture's clock ran on since the balls stopped
};

}  // namespace nineball::window
