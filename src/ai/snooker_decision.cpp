// Snooker's choices after a foul (WPBSA 3.15, and 3.14 after a miss): play from where the
// balls lie, put the offender back in, or (after a miss) have the balls replaced and the
// offender play the stroke again. Each is judged by planning the stroke that follows it: the
// chooser's own worth when he plays, one less the offender's when the offender plays.
#include <algorithm>

#include "common/log.hpp"
#include "nineball/planner.hpp"
#include "nineball/snooker_rack.hpp"

namespace nineball::ai {
namespace {

const char* choiceName(bool replace, bool play) {
  if (replace) return "replace";
  return play ? "play" : "put back";
}

}  // namespace

TurnInput Planner::decideAfterFoul(const Match& match) {
  const PlanInput in = planInputFrom(match);
  double thinking = 0.0;
  auto worthTo = [&](const PlanInput& after, bool chooser_plays) {
    const double v = plan(after).value;
    thinking += last_think_seconds_;
    return chooser_plays ? v : 1.0 - v;
  };

  PlanInput play_on = in;
  play_on.rack.decide(true);
  const double play = worthTo(play_on, true);
  PlanInput put_back = in;
  put_back.rack.decide(false);
  const double back = worthTo(put_back, false);

  TurnInput turn;
  turn.kind = TurnInput::Kind::Decision;
  turn.shoot = play >= back;
  double best = std::max(play, back);
  if (in.rack.pendingDecision() == rules::Decision::PlayPutBackOrReplace &&
      !match.ballsBeforeShot().empty()) {
    // The balls go back where they were before the miss and the offender plays it again, from
    // where his cue ball lay (not in hand: rules::replaceAfterMiss).
    PlanInput replaced = in;
    replaced.balls = match.ballsBeforeShot();
    rules::replaceAfterMiss(replaced.rack);
    replaced.cue_in_hand = false;
    const double replace = worthTo(replaced, false);
    if (replace > best) {
      best = replace;
      turn.shoot = false;
      turn.replace = true;
    }
  }
  last_think_seconds_ = thinking;
  logger("ai")->info("{}: after the foul: {} ({:.3f})", levelName(level_),
                     choiceName(turn.replace, turn.shoot), best);
  return turn;
}

}  // namespace nineball::ai
