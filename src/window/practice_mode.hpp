#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nineball/match.hpp"
#include "render/hud_state.hpp"
#include "window/practice_table.hpp"

namespace nineball::window {

/// What practice asks of the session it runs in. Passed to each call rather than kept, as the
/// session moves.
class PracticeHost {
 public:
  /// True while the player sets up a shot (balls are moved by hand only then).
  virtual bool aiming() const = 0;
  /// The session's table set up afresh from the practice layout: no rules carry over.
  virtual void rebuildPractice() = 0;
  /// The cue as `shot` was played: aim, power, spin and tilt.
  virtual void takeCue(const PracticeShot& shot) = 0;
  virtual void say(const std::string& text, render::Tone tone) = 0;

 protected:
  ~PracticeHost() = default;
};

/// The session's practice part: no rules and no turns; any ball placed anywhere, added or taken
/// away; the last shot undone or retried; what the player is told of each.
class PracticeMode {
 public:
  /// Practice from `racked`'s balls (its game's rack, or a layout of the player's).
  explicit PracticeMode(const Match& racked);

  const PracticeTable& table() const { return table_; }
  /// The game's balls off the practice table (the tray's), in number order.
  std::vector<int> offTable() const;

  std::optional<std::string> placementProblem(int id, Vec2 pos) const {
    return table_.placementProblem(id, pos);
  }
  /// Moves a ball; false (and a message) when it does not fit there.
  bool moveBall(PracticeHost& host, int id, Vec2 pos);
  /// Takes ball `id` off the table, or puts it on (at `near`, or the nearest free spot).
  void toggleBall(PracticeHost& host, int id, Vec2 near);
  /// Back to before the last shot (with its cue) or the last ball moved by hand.
  void undo(PracticeHost& host);
  /// The last shot's position and cue again.
  void retry(PracticeHost& host);
  /// A shot about to be played from the layout as it stands, with this cue.
  void recordShot(const Shot& shot);
  /// The balls at rest after the shot: what went down is said, a dropped cue ball comes back.
  void finishShot(PracticeHost& host, const std::vector<BallState>& after);

 private:
  PracticeTable table_;
  std::vector<int> racked_;  // every object ball of the game (GameDef::balls: sorted)
};

}  // namespace nineball::window
