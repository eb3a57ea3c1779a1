#include "play/jump_shot.hpp"

#include <cmath>

namespace nineball::play {
namespace {

bool touchesBall(const Event& e, int cue) {
  return e.type == EventType::BallBall && (e.a == cue || e.b == cue);
}

bool endsFlight(const Event& e, int cue) {
  return e.a == cue && (e.type == EventType::Land || e.type == EventType::OffTable);
}

// The balls whose centre is within 2R of the segment from `from` to `to`, strictly between its
// ends.
void addPassedOver(Vec2 from, Vec2 to, const std::vector<BallState>& before, double radius, int cue,
                   std::vector<int>& out) {
  const double span = length(to - from);
  if (span <= 0.0) return;
  const Vec2 dir = (to - from) / span;
  for (const BallState& b : before) {
    if (b.id == cue || b.pocket) continue;
    const Vec2 rel = b.pos - from;
    const double along = dot(rel, dir);
    if (along > 0.0 && along < span && std::abs(cross(dir, rel)) < 2.0 * radius) {
      out.push_back(b.id);
    }
  }
}

}  // namespace

std::vector<int> ballsJumpedOver(const std::vector<Event>& events,
                                 const std::vector<BallState>& before, double ball_radius,
                                 int cue) {
  std::vector<int> over;
  bool flying = false;
  Vec2 from;  // where the flight (or its part since a cushion) began
  for (const Event& e : events) {
    if (touchesBall(e, cue)) break;
    if (e.a != cue) continue;
    if (e.type == EventType::Airborne) {
      flying = true;
      from = e.at;
    } else if (flying && (endsFlight(e, cue) || e.type == EventType::Cushion)) {
      addPassedOver(from, e.at, before, ball_radius, cue, over);
      flying = e.type == EventType::Cushion;  // a cushion met in the air: flying on from it
      from = e.at;
    }
  }
  return over;
}

}  // namespace nineball::play
