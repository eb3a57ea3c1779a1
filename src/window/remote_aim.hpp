#pragma once

#include <optional>

#include "nineball/vec2.hpp"

// The other player's cue as this window shows it: aim messages come a few times a second, the
// frames many more, so the cue eases towards the last one heard instead of jumping. No SFML.
namespace nineball::window {

/// One aim: what an Aim message carries.
struct AimPose {
  double heading_rad = 0.0;
  double speed = 0.0;  ///< m/s
  Vec2 tip;            ///< fraction of R
  double elevation_rad = 0.0;
  std::optional<Vec2> cue;  ///< the cue ball in hand, where it is being placed (m)
};

/// Eases the pose shown towards the one last heard.
class AimSmoother {
 public:
  /// s: the pose shown covers 63 % of the way to a new aim in this time; 8 messages a second
  /// arrive 0.125 s apart, so the cue reaches each aim about as the next comes.
  static constexpr double kEase = 0.08;

  /// The aim heard last; the first one is shown at once.
  void heard(const AimPose& pose);
  /// Moves the pose shown `seconds` on; nothing before the first aim.
  std::optional<AimPose> advance(double seconds);
  /// Forgets the aim (a new turn begins).
  void reset();

 private:
  std::optional<AimPose> target_;
  std::optional<AimPose> shown_;
};

/// The heading turned from `from` towards `to` by `fraction` of the way, the short way round.
double easeAngle(double from, double to, double fraction);

/// Aim messages at most every kPeriod seconds, and only when the aim changed.
class AimThrottle {
 public:
  static constexpr double kPeriod = 0.125;  ///< 8 a second (the brief's "at most ~8 a second")

  /// True when `pose` should be sent now (`now` in seconds, any origin).
  bool due(const AimPose& pose, double now);
  void reset() { last_.reset(); }

 private:
  std::optional<AimPose> last_;
  double sent_at_ = 0.0;
};

}  // namespace nineball::window
