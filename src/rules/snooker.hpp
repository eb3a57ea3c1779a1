#pragma once

#include "nineball/rules.hpp"

namespace nineball::rules {

/// Snooker under the WPBSA's Official Rules of the Games of Snooker and English Billiards
/// (section 3), as a pure state machine (docs/cli.md, "Snooker", says what is judged and how):
/// a red, then a colour of the striker's nomination while reds remain, then the colours in
/// ascending order; colours potted while reds remain (and the colour after the last red) are
/// re-spotted; fouls give the opponent the value of the ball on or of the highest ball
/// involved, 4 to 7; after a foul the opponent plays or puts the offender back in (a miss also
/// offers the balls replaced); a free ball when the match states the incoming striker
/// snookered; a frame level on the black is decided on a re-spotted black.
///
/// The nomination is ShotSummary::call's ball; without a call the nominated ball is the first
/// colour (or, on a free ball, the first ball) the cue ball hits.
class SnookerRules : public RuleBook {
 public:
  Game game() const override { return Game::Snooker; }
  RuleSet ruleSet() const override { return RuleSet::Wpbsa; }
  /// The balls on (snooker_balls.hpp ballsOn); on a free ball every ball on the table.
  std::vector<int> legalFirstBalls(const RackState& s) const override;
  bool callRequired(const RackState&) const override { return false; }
  Verdict judge(RackState& s, const ShotSummary& shot, bool push_out) const override;
  int pointsRemaining(const RackState& s) const override;
};

}  // namespace nineball::rules
