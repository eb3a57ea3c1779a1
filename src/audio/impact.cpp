#include "audio/impact.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::audio {
namespace {

Vec2 velocityOf(const std::vector<BallState>& balls, int id) {
  for (const BallState& b : balls) {
    if (b.id == id) return b.vel;
  }
  return {};
}

}  // namespace

std::vector<Impact> impactsFromEvents(const std::vector<Event>& events,
                                      const std::vector<BallState>& before) {
  std::vector<Impact> out;
  for (const Event& e : events) {
    switch (e.type) {
      case EventType::BallBall: {
        const double da = length(e.va - velocityOf(before, e.a));
        const double db = length(e.vb - velocityOf(before, e.b));
        out.push_back({ImpactKind::Ball, std::max(da, db)});
        break;
      }
      case EventType::Cushion:
        out.push_back({ImpactKind::Cushion, length(e.va - velocityOf(before, e.a))});
        break;
      case EventType::Pocket:
        out.push_back({ImpactKind::Pocket, length(velocityOf(before, e.a))});
        break;
      case EventType::AllAtRest:
      case EventType::Miscue:  // the tip slips off: no ball moves
      case EventType::Airborne:
      case EventType::OffTable:
        break;
      case EventType::Land:  // the slate sounds as a cushion does, by the speed it took away
        out.push_back({ImpactKind::Cushion, 0.0});
        break;
    }
  }
  return out;
}

double impactVolume(const Impact& impact) {
  // Speed changes at which each sound is at full volume, and below which it is not heard.
  double full = 6.0;
  if (impact.kind == ImpactKind::Cushion) full = 4.0;
  if (impact.kind == ImpactKind::Pocket) full = 3.0;
  if (impact.kind == ImpactKind::Cue) full = 8.0;  // a firm break
  constexpr double kSilent = 0.01;
  if (!(impact.strength > kSilent)) return 0.0;
  const double v = 100.0 * std::pow(std::min(1.0, impact.strength / full), 0.6);
  // A pocket is heard even when the ball creeps in.
  return impact.kind == ImpactKind::Pocket ? std::max(v, 25.0) : v;
}

}  // namespace nineball::audio
