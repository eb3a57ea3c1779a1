#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/table.hpp"

namespace nineball::window {

/// A shot as the player set it up in practice: the position it was played from and the cue.
struct PracticeShot {
  std::vector<BallState> layout;
  double heading = 0.0;
  double speed = 0.0;
  Vec2 tip;
  double elevation = 0.0;
};

/// What undo goes back over: a shot, or a ball moved, added or taken away by hand.
struct PracticeStep {
  PracticeShot before;  ///< the position before it (and, for a shot, the cue it was played with)
  bool shot = false;
};

/// The table of practice mode, without rules: any ball placed anywhere it fits, added or
/// taken away, and the shots played from it kept so that the last can be undone or retried.
/// No SFML, no physics: the session plays the shots.
class PracticeTable {
 public:
  PracticeTable(const TableGeometry& table, double ball_radius, std::vector<BallState> layout);

  /// The balls on the table now, at rest (pocketed ones are gone; the cue ball is always on).
  const std::vector<BallState>& layout() const { return layout_; }
  bool has(int id) const;

  /// Why ball `id` may not stand at `pos` (off the table, on another ball), or nothing.
  std::optional<std::string> placementProblem(int id, Vec2 pos) const;
  /// Moves (or adds) ball `id` to `pos`; false when it does not fit there. Undo takes it back.
  bool place(int id, Vec2 pos);
  /// Takes an object ball off the table; the cue ball stays. Undo puts it back.
  bool remove(int id);
  /// A free spot for a ball, the nearest to `near` found on rings round it.
  std::optional<Vec2> freeSpotNear(int id, Vec2 near) const;

  /// Remembers the position and cue of a shot about to be played.
  void recordShot(PracticeShot shot);
  /// The balls at rest after a shot: those pocketed leave the table, but a pocketed cue ball
  /// comes back to where it was struck from. True when the cue ball had to come back.
  bool settle(const std::vector<BallState>& after);
  /// The last shot's position and cue, to play it again: the last shot played, even when
  /// undo has since gone back over it.
  std::optional<PracticeShot> retry();
  /// Back to before the last step (a shot or a ball moved by hand), which is forgotten: undo
  /// again goes one step further.
  std::optional<PracticeStep> undo();
  std::size_t stepsRemembered() const { return steps_.size(); }

 private:
  TableGeometry table_;
  double r_;
  std::vector<BallState> layout_;
  void recordMove();

  std::vector<PracticeStep> steps_;
  std::optional<PracticeShot> last_shot_;
};

}  // namespace nineball::window
