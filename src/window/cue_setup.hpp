#pragma once

#include <optional>

#include "nineball/vec2.hpp"

namespace nineball::window {

/// The cue as the player to move sets it before a shot: the aim (a heading), the power (the
/// speed the cue ball gets), the tip's offset from the ball's centre (spin), the cue's tilt,
/// and the cue ball's spot while it is in hand. Each is held within its range; how far the tip
/// may go and which spot is legal are the session's to say (the physics, the rules). No SFML.
class CueSetup {
 public:
  static constexpr double kMaxSpeed = 12.0;         ///< m/s at full power (a hard break)
  static constexpr double kMinSpeed = 0.1;          ///< m/s at the bottom of the gauge
  static constexpr double kMaxElevationDeg = 60.0;  ///< the cue's tilt: swerve up to a masse

  explicit CueSetup(double speed) : speed_(speed) {}

  double heading() const { return heading_; }
  void setHeading(double radians) { heading_ = radians; }
  double speed() const { return speed_; }
  /// Sets the speed, held within kMinSpeed to kMaxSpeed.
  void setSpeed(double mps);
  /// The gauge, 0 to 1, linear in speed from kMinSpeed to kMaxSpeed.
  double power() const { return (speed_ - kMinSpeed) / (kMaxSpeed - kMinSpeed); }
  void setPower(double fraction);
  Vec2 tip() const { return tip_; }
  /// Sets the tip, pulled in to a hair inside `max_tip` (past it the physics calls the shot a
  /// miscue).
  void setTip(Vec2 tip, double max_tip);
  /// The cue's tilt above the table, radians.
  double elevation() const { return elevation_; }
  /// Sets the tilt, held within 0 to kMaxElevationDeg.
  void setElevation(double radians);
  /// A shot's own settings taken as they were played (the computer's shot, a practice shot
  /// again): the speed held in range, the tip and tilt as given.
  void take(double heading, double speed, Vec2 tip, double elevation);
  /// A new turn: the tip back in the centre, the cue level, no cue ball in hand placed yet.
  void newTurn();

  /// Where the cue ball in hand stands (nothing: not placed, or not in hand).
  const std::optional<Vec2>& spot() const { return spot_; }
  void setSpot(std::optional<Vec2> spot) { spot_ = spot; }

 private:
  double heading_ = 0.0;
  double speed_;
  Vec2 tip_;
  double elevation_ = 0.0;
  std::optional<Vec2> spot_;
};

}  // namespace nineball::window
