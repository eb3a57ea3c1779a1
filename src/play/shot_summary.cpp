#include "play/shot_summary.hpp"

#include <set>

#include "nineball/ball.hpp"

namespace nineball::play {

rules::ShotSummary summarize(const std::vector<Event>& events) {
  rules::ShotSummary s;
  std::set<int> to_rail;
  for (const Event& e : events) {
    switch (e.type) {
      case EventType::BallBall:
        if (!s.first_contact && (e.a == kCueBall || e.b == kCueBall)) {
          s.first_contact = e.a == kCueBall ? e.b : e.a;
        }
        break;
      case EventType::Cushion:
        if (s.first_contact) s.rail_after_contact = true;
        if (e.a != kCueBall) to_rail.insert(e.a);
        break;
      case EventType::Pocket:
        if (e.a == kCueBall) {
          s.cue_pocketed = true;
        } else {
          s.pocketed.push_back(e.a);
          s.pockets.push_back(e.pocket);
        }
        break;
      case EventType::AllAtRest:
      case EventType::Miscue:  // the cue ball never moved: no contact follows
        break;
    }
  }
  s.object_balls_to_rail = static_cast<int>(to_rail.size());
  return s;
}

}  // namespace nineball::play
