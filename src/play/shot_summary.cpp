#include "play/shot_summary.hpp"

#include <set>

namespace nineball::play {

rules::ShotSummary summarize(const std::vector<Event>& events, int cue) {
  rules::ShotSummary s;
  std::set<int> to_rail;
  for (const Event& e : events) {
    switch (e.type) {
      case EventType::BallBall:
        if (e.a == cue || e.b == cue) {
          const int other = e.a == cue ? e.b : e.a;
          if (!s.first_contact) s.first_contact = other;
          s.cue_touches.push_back(other);
          s.cue_cushions_before.push_back(s.cue_cushions);
        }
        break;
      case EventType::Cushion:
        if (s.first_contact) s.rail_after_contact = true;
        if (e.a == cue) {
          ++s.cue_cushions;
        } else {
          to_rail.insert(e.a);
        }
        break;
      case EventType::Pocket:
        if (e.a == cue) {
          s.cue_pocketed = true;
        } else {
          s.pocketed.push_back(e.a);
          s.pockets.push_back(e.pocket);
        }
        break;
      case EventType::Miscue:  // the cue ball never moved: no contact follows
        s.miscue = true;
        break;
      case EventType::AllAtRest:
      case EventType::Airborne:  // a flight is no contact: a jump is a legal stroke
      case EventType::Land:
        break;
      case EventType::OffTable:
        s.off_table.push_back(e.a);
        // Off the table the cue ball is in hand for the next player, as after a scratch (WPA
        // General Rules, "Cue Ball Scratch or off the Table"; WPBSA: in hand in the D).
        if (e.a == cue) s.cue_pocketed = true;
        break;
    }
  }
  s.object_balls_to_rail = static_cast<int>(to_rail.size());
  return s;
}

}  // namespace nineball::play
