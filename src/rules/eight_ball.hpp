#pragma once

#include "nineball/rules.hpp"

namespace nineball::rules {

/// Eight-ball under WPA rules, shots called only for the 8. The break must pocket a ball or
/// drive four object balls to a cushion, else the opponent re-racks or plays on; the 8 on the
/// break is spotted. The table stays open after the break until a legal pot sets the groups.
/// The shooter's group is hit first, the 8 once the group is cleared. The 8 down early, in an
/// uncalled pocket or on a foul loses. Every foul gives ball in hand anywhere.
class EightBallRules : public RuleBook {
 public:
  Game game() const override { return Game::EightBall; }
  RuleSet ruleSet() const override { return RuleSet::Wpa; }
  std::vector<int> legalFirstBalls(const RackState& s) const override;
  bool callRequired(const RackState& s) const override;
  Verdict judge(RackState& s, const ShotSummary& shot, bool push_out) const override;

 private:
  Verdict judgeBreak(RackState& s, const ShotSummary& shot) const;
};

}  // namespace nineball::rules
