#pragma once

#include <string>

#include "window/game_session.hpp"

namespace nineball::window {

/// A player at another computer (online play): while it holds the turn the keyboard and the
/// mouse must not play it, and the frame shows its cue as it aims over there. OnlinePlay is
/// one; a RemoteSeat (seats.hpp) puts it in a seat.
class RemoteControl {
 public:
  virtual ~RemoteControl() = default;
  /// True while this window must not play: the other side's move, or no settled link.
  virtual bool controls(const GameSession& session) const = 0;
  /// True when the other side's cue is shown (it is aiming).
  virtual bool showsCue() const = 0;
  /// How far its cue is drawn back (m).
  virtual double pull() const = 0;
  /// The status line meanwhile.
  virtual std::string status(const GameSession& session) const = 0;
};

}  // namespace nineball::window
