#pragma once

#include "nineball/rules.hpp"

namespace nineball::rules {

/// Ten-ball under WPA rules: nine-ball's fouls, break and push-out, with the 10 as the game
/// ball and every shot after the break called, ball and pocket. A pot not as called ends the
/// turn (no foul) and the opponent may play or pass it back; the 10 then, on the break, on a
/// foul or on a push-out is spotted. Three fouls in a row lose.
class TenBallRules : public RuleBook {
 public:
  Game game() const override { return Game::TenBall; }
  RuleSet ruleSet() const override { return RuleSet::Wpa; }
  std::vector<int> legalFirstBalls(const RackState& s) const override;
  bool callRequired(const RackState& s) const override { return !s.break_next; }
  Verdict judge(RackState& s, const ShotSummary& shot, bool push_out) const override;
};

}  // namespace nineball::rules
