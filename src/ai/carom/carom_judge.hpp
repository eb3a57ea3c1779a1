#pragma once

#include <cstdint>
#include <vector>

#include "nineball/planner.hpp"

namespace nineball::ai {

/// What one carom shot did: whether it scored, and (run to rest) where the balls stopped and
/// the rack after it.
struct CaromOutcome {
  bool point = false;
  bool touched_both = false;  ///< the shooter's ball met both object balls
  int cushions = 0;           ///< before the second ball (or in all): what a point needs 3 of
  std::vector<BallState> balls;
  rules::Rack rack{rules::Game::ThreeCushion, rules::RuleSet::Umb, {}, false};
};

/// Plays carom shots from one position through the physics and judges them with the rules.
/// Safe to call from several threads: each thread keeps its own world, reset between shots.
class CaromJudge {
 public:
  explicit CaromJudge(const PlanInput& in);

  /// The shot struck on the shooter's ball. `to_rest`: run until every ball stops (for the
  /// position it leaves); otherwise only until the point is decided.
  CaromOutcome run(const Shot& shot, bool to_rest) const;

  int cue() const { return cue_; }
  const PlanInput& input() const { return in_; }

 private:
  PlanInput in_;
  int cue_;
  std::uint64_t id_;
};

}  // namespace nineball::ai
