#pragma once

#include "ai/planner_candidates.hpp"
#include "ai/planner_evaluate.hpp"

// Position play by simulation: the shot after a candidate is played through the physics
// instead of being estimated from the geometry of where the cue ball stops.
namespace nineball::ai {

/// A candidate's worth with the next shot simulated, and the shots that took.
struct LookAhead {
  double value = 0.0;
  long simulations = 0;
};

/// When the candidate's nominal outcome keeps the table, the shooter's easiest pots from
/// there (the level's lookahead lines, speeds and tips) are simulated too. Their worth replaces
/// the geometric estimate: 0.55 + 0.4 x the best, over the pots that really drop and keep the
/// table, of the line's chance for the judging aim times how good the position they leave is
/// (0.75 + 0.25 x its own next chance; 1 when it wins). Any other outcome keeps its usual
/// worth.
LookAhead lookAhead(const SearchContext& ctx, const Evaluator& eval, const Candidate& c);

}  // namespace nineball::ai
