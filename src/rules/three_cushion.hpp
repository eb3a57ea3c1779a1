#pragma once

#include "nineball/rules.hpp"

namespace nineball::rules {

/// Three-cushion carom under the UMB's world rules (chapter V, art. 83, and the common rules of
/// chapter III): three balls, the opener's white (0), the other's yellow (1) and the red (2). A
/// point when the shooter's ball touches both object balls and has met three cushions or more
/// before it touches the second; the shooter plays on while scoring. The opening shot, and the
/// first after the balls were set up again, is played straight onto the red. The game is to
/// RackState::target points with equal innings: when the opener reaches the distance the other
/// plays one last inning, and a game both finish ends level.
class ThreeCushionRules : public RuleBook {
 public:
  static constexpr int kWhite = 0;
  static constexpr int kYellow = 1;
  static constexpr int kRed = 2;

  Game game() const override { return Game::ThreeCushion; }
  RuleSet ruleSet() const override { return RuleSet::Umb; }
  /// Both object balls; on the opening shot the red alone.
  std::vector<int> legalFirstBalls(const RackState& s) const override;
  /// The red: the ball the HUD and the opening name.
  int ballOn(const RackState& s) const override;
  int cueBall(const RackState& s) const override;
  bool callRequired(const RackState&) const override { return false; }
  Verdict judge(RackState& s, const ShotSummary& shot, bool push_out) const override;

  /// The cushions the cue ball met before it touched its second object ball, or in the whole
  /// shot when it did not touch two; and whether it touched two.
  static int cushionsBeforeSecond(const ShotSummary& shot, int cue, bool& touched_both);
};

}  // namespace nineball::rules
