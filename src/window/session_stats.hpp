#pragma once

#include <array>
#include <string>
#include <vector>

#include "nineball/match.hpp"

namespace nineball::window {

/// One player's figures over the session (every rack since the window opened).
struct PlayerStats {
  int pots = 0;         ///< object balls pocketed on shots without a foul (the break too)
  int fouls = 0;        ///< shots that fouled
  int breaks = 0;       ///< racks broken
  int break_balls = 0;  ///< object balls pocketed on those breaks
  int run_outs = 0;     ///< racks won in the player's first visit, without missing
  int racks_won = 0;

  bool operator==(const PlayerStats& o) const;
};

/// The session's statistics, per seat, kept up from the turn records. No SFML.
class SessionStats {
 public:
  /// A rack begins: visits are counted afresh.
  void startRack();
  /// One turn's record, played by `seat`; `was_break` for the rack's opening break.
  void record(int seat, const TurnRecord& turn, bool was_break);

  const PlayerStats& seat(int s) const { return seats_[s]; }
  /// "pots 5  fouls 1  breaks 2 (3 down)  run-outs 1", for the end-of-rack dialog.
  std::string line(int s) const;

 private:
  std::array<PlayerStats, 2> seats_{};
  std::array<int, 2> visits_{};  // visits to the table this rack
  int last_shooter_ = -1;        // seat of the rack's last shot, -1 before the first
};

}  // namespace nineball::window
