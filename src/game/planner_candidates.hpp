#pragma once

#include <optional>
#include <vector>

#include "game/planner_evaluate.hpp"
#include "nineball/planner.hpp"
#include "nineball/table.hpp"

// The shots a planner tries, before any simulation: ghost-ball pots at every pocket,
// combinations, banks, kicks off a cushion, safeties; and, with the cue ball in hand, where to
// put it.
namespace nineball::ai {

/// What every generator reads: the position, the table as built, the level.
struct SearchContext {
  const PlanInput& in;
  const TableGeometry& table;
  const LevelSettings& level;
  double radius = 0.0;
  int ball_on = 0;
};

/// Every shot worth simulating with the cue ball at `cue`. `balls` holds the cue ball there;
/// `placed` is the position to report when the cue ball is being placed.
std::vector<Candidate> shotsFrom(const SearchContext& ctx, const std::vector<BallState>& balls,
                                 Vec2 cue, std::optional<Vec2> placed);

/// Only the pots of the ball on into `pocket` from `cue` (the mouth's middle), every speed and
/// tip of the level.
std::vector<Candidate> potsInto(const SearchContext& ctx, const std::vector<BallState>& balls,
                                Vec2 cue, PocketId pocket, std::optional<Vec2> placed);

/// Every direction round the cue ball at `headings` even steps, at a few speeds: the last
/// resort when no aimed shot avoids a foul.
std::vector<Candidate> sweepShots(const SearchContext& ctx, int headings);

/// The opening break: the cue ball behind the head string, hard at the ball on.
std::vector<Candidate> breakShots(const SearchContext& ctx, const Evaluator& eval);

/// Ball in hand: pots from the best places to put the cue ball (behind the ball on, on its
/// lines to the pockets), or safeties from a few clear spots when nothing can be potted.
std::vector<Candidate> inHandShots(const SearchContext& ctx, const Evaluator& eval);

}  // namespace nineball::ai
