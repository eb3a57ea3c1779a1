#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "nineball/seat.hpp"
#include "window/computer_player.hpp"
#include "window/game_session.hpp"
#include "window/seats/remote_control.hpp"

namespace nineball::window {

/// A person at this computer: the keyboard and the mouse play the seat's turns.
struct LocalSeat {};
/// The computer: its planner plays the seat's turns, shown as a player makes them. (Named apart
/// from nineball::ComputerSeat, the public choice of who plays a seat, which makes this one.)
struct PlannerSeat {
  const ComputerPlayer* player;
};
/// A player at another computer (online), whose turns come over the link.
struct RemoteSeat {
  const RemoteControl* remote;
};

/// Who plays one seat at this window. Adding a kind of player is one more alternative here and
/// its answers in seats.cpp (the one turn pipeline visits the seat); nothing else changes.
using WindowSeat = std::variant<LocalSeat, PlannerSeat, RemoteSeat>;

/// The two seats at the window and the one turn pipeline for all their kinds: whose move it is,
/// whether the keyboard and the mouse may play it, who shows the cue and how far it is drawn
/// back, what the status line says, and who plays the shot. Owns the computer player (it plays
/// Player 2's seat when that seat's opponent is the computer, and reaps its dropped plans
/// otherwise); the remote player is lent by the online game.
class Seats {
 public:
  /// `seed` fixes the computer's cueing errors (the game's --seed).
  explicit Seats(std::uint64_t seed) : computer_(seed) {}
  Seats(const Seats&) = delete;
  Seats& operator=(const Seats&) = delete;

  ComputerPlayer& computer() { return computer_; }
  const ComputerPlayer& computer() const { return computer_; }

  /// Player 2's opponent as chosen (human or the computer at a level).
  const Seat& opponent() const { return computer_.opponent(); }
  /// Gives Player 2's seat to a person or to the computer at a level, and names the seat.
  void setOpponent(GameSession& session, const Seat& opponent) {
    computer_.setOpponent(session, opponent);
  }
  /// Online: the player at the other computer takes `seat` (and holds the table while its link
  /// is not settled); the other seat is this computer's player's.
  void setRemote(int seat, const RemoteControl& remote);
  /// The online game is over: both seats are played here again.
  void clearRemote() { remote_.reset(); }

  /// Who plays `seat` (0 or 1) now.
  WindowSeat seat(int index) const;
  /// The seat whose player has the table now: the seat to move's, but a remote player's while it
  /// says it holds the table (its move, or a link not yet settled).
  WindowSeat mover(const GameSession& session) const;

  /// True while the turn is not this computer's person's: the keyboard and the mouse must not
  /// play it.
  bool controls(const GameSession& session) const;
  /// True once the player with the table holds its cue at the aim (the cue and the guide show).
  bool showsCue(const GameSession& session) const;
  /// How far that cue is drawn back now (m).
  double pull(const GameSession& session) const;
  /// Where the cue ball is while the computer carries it to its spot.
  std::optional<Vec2> carriedCue() const { return computer_.carriedCue(); }
  /// What the status line says while the turn is not this computer's person's.
  std::string status(const GameSession& session) const;

  /// One frame of `seconds`: the computer plans, shows and plays its shot (a remote player's
  /// moves come through the online game's own update).
  void update(GameSession& session, double seconds) { computer_.update(session, seconds); }

 private:
  struct Remote {
    int seat;
    const RemoteControl* control;
  };

  ComputerPlayer computer_;
  std::optional<Remote> remote_;
};

}  // namespace nineball::window
