#pragma once

#include <vector>

#include "nineball/ball.hpp"
#include "nineball/event.hpp"

namespace nineball::audio {

enum class ImpactKind { Ball, Cushion, Pocket, Cue };

/// Something that makes a sound, with how hard it was: the speed change it caused (m/s),
/// which is the impulse per unit mass.
struct Impact {
  ImpactKind kind = ImpactKind::Ball;
  double strength = 0.0;
};

/// The impacts of events found in one step; `before` holds the balls' velocities at the
/// start of that step (a ball-ball click is as loud as the larger change of either ball's
/// velocity, a cushion thud as its ball's, a pocket drop as its ball's speed).
std::vector<Impact> impactsFromEvents(const std::vector<Event>& events,
                                      const std::vector<BallState>& before);

/// The cue's tip striking the cue ball at `speed` (m/s, the speed it gives the ball).
inline Impact cueStrike(double speed) {
  return {ImpactKind::Cue, speed};
}

/// Volume 0-100 for an impact: a power law of its strength, full at a hard break.
double impactVolume(const Impact& impact);

}  // namespace nineball::audio
