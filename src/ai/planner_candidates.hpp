#pragma once

#include <optional>
#include <vector>

#include "ai/planner_evaluate.hpp"
#include "nineball/planner.hpp"
#include "nineball/table.hpp"

// The shots a planner tries, before any simulation: ghost-ball pots at every pocket,
// combinations, banks, kicks off a cushion, safeties; and, with the cue ball in hand, where to
// put it.
namespace nineball::ai {

/// What every generator reads: the position, the table as built, the level, and the balls the
/// cue ball may hit first (the ball on; in a game of groups, the shooter's group,
/// any but the 8 on an open table, or the 8), lowest first.
struct SearchContext {
  const PlanInput& in;
  const TableGeometry& table;
  const LevelSettings& level;
  double radius = 0.0;
  std::vector<int> targets;
  /// The aim error (rad) a pot line's chance (its prior) is reckoned for.
  double prior_sigma = degToRad(kReferenceAimDeg);

  /// The lowest target (0 when none is left).
  int firstTarget() const { return targets.empty() ? 0 : targets.front(); }
};

/// Every shot worth simulating with the cue ball at `cue`. `balls` holds the cue ball there;
/// `placed` is the position to report when the cue ball is being placed.
std::vector<Candidate> shotsFrom(const SearchContext& ctx, const std::vector<BallState>& balls,
                                 Vec2 cue, std::optional<Vec2> placed);

/// Only the pots of `ball` into `pocket` from `cue` (the mouth's middle), every speed and tip
/// of the level.
std::vector<Candidate> potsInto(const SearchContext& ctx, const std::vector<BallState>& balls,
                                Vec2 cue, int ball, PocketId pocket, std::optional<Vec2> placed);

/// The straight pots alone from `cue`, the easiest `lines` of them, at `speeds` and `tips`:
/// what a look one shot further ahead tries.
std::vector<Candidate> plainPots(const SearchContext& ctx, const std::vector<BallState>& balls,
                                 Vec2 cue, int lines, const std::vector<double>& speeds,
                                 const std::vector<Vec2>& tips);

/// Push-outs from where the cue ball lies: `headings` even directions at a few soft speeds.
std::vector<Candidate> pushOutShots(const SearchContext& ctx, int headings);

/// Fills in the call of every candidate when the rules need one: the ball meant to drop and
/// its pocket, or for a shot that means to drop nothing the ball it hits first and the pocket
/// nearest to it. Push-outs need none.
void assignCalls(const SearchContext& ctx, std::vector<Candidate>& cands);

/// Every direction round the cue ball at `headings` even steps, at a few speeds: the last
/// resort when no aimed shot avoids a foul.
std::vector<Candidate> sweepShots(const SearchContext& ctx, int headings);

/// The opening break: the cue ball behind the head string, hard at the ball on.
std::vector<Candidate> breakShots(const SearchContext& ctx, const Evaluator& eval);

/// Ball in hand: pots from the best places to put the cue ball (behind the ball on, on its
/// lines to the pockets), or safeties from a few clear spots when nothing can be potted.
std::vector<Candidate> inHandShots(const SearchContext& ctx, const Evaluator& eval);

}  // namespace nineball::ai
