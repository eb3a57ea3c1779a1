#include "window/session_stats.hpp"

namespace nineball::window {

bool PlayerStats::operator==(const PlayerStats& o) const {
  return pots == o.pots && fouls == o.fouls && breaks == o.breaks && break_balls == o.break_balls &&
         run_outs == o.run_outs && racks_won == o.racks_won;
}

void SessionStats::startRack() {
  visits_ = {0, 0};
  last_shooter_ = -1;
}

void SessionStats::record(int seat, const TurnRecord& turn, bool was_break) {
  if (seat < 0 || seat > 1) return;
  PlayerStats& p = seats_[seat];
  // A decision after a push-out is no visit to the table: the shooter's visit goes on.
  if (turn.kind != TurnInput::Kind::Decision) {
    if (was_break) startRack();
    if (seat != last_shooter_) ++visits_[seat];
    last_shooter_ = seat;
    const int down = static_cast<int>(turn.verdict.pocketed.size());
    if (turn.verdict.legal()) {
      p.pots += down;
    } else {
      ++p.fouls;
    }
    if (was_break) {
      ++p.breaks;
      p.break_balls += down;
    }
  }
  if (turn.verdict.winner) {
    // The shooter (the 9 down legally) or the opponent (the shooter's third foul in a row).
    const int winner = turn.verdict.winner == turn.shooter ? seat : 1 - seat;
    ++seats_[winner].racks_won;
    if (visits_[winner] == 1 && winner == seat) ++seats_[winner].run_outs;
    startRack();
  }
}

std::string SessionStats::line(int s) const {
  const PlayerStats& p = seats_[s];
  std::string out = "pots " + std::to_string(p.pots) + "  fouls " + std::to_string(p.fouls) +
                    "  breaks " + std::to_string(p.breaks);
  if (p.breaks > 0) out += " (" + std::to_string(p.break_balls) + " down)";
  out += "  run-outs " + std::to_string(p.run_outs);
  return out;
}

}  // namespace nineball::window
