#pragma once

#include "nineball/rules.hpp"

namespace nineball::rules {

/// Nine-ball: WPA (break, push-out, three fouls, the 9 spotted on a foul) or the seed paper's
/// simpler machine (no break rules, a scratch sends the cue ball to the head spot).
class NineBallRules : public RuleBook {
 public:
  explicit NineBallRules(RuleSet rules) : rules_(rules) {}
  Game game() const override { return Game::NineBall; }
  RuleSet ruleSet() const override { return rules_; }
  std::vector<int> legalFirstBalls(const RackState& s) const override;
  bool callRequired(const RackState&) const override { return false; }
  Verdict judge(RackState& s, const ShotSummary& shot, bool push_out) const override;

 private:
  Verdict judgeWpa(RackState& s, const ShotSummary& shot, bool push_out) const;
  Verdict judgePaper(RackState& s, const ShotSummary& shot) const;

  RuleSet rules_;
};

}  // namespace nineball::rules
