#include "ai/planner_lookahead.hpp"

#include <algorithm>

#include "ai/planner_geometry.hpp"

namespace nineball::ai {
namespace {

// How much of a pot's worth is the pot itself, and how much the position it leaves.
constexpr double kPotShare = 0.75;
constexpr double kLeaveShare = 0.25;

}  // namespace

LookAhead lookAhead(const SearchContext& ctx, const Evaluator& eval, const Candidate& c) {
  LookAhead out;
  out.simulations = 1;
  const std::optional<Outcome> o = eval.outcome(c, c.shot);
  if (!o) return out;
  out.value = eval.score(*o);
  const rules::Verdict& v = o->verdict;
  const BallState* cue = findOnTable(o->balls, kCueBall);
  if (v.winner || v.next != ctx.in.rack.shooter() || v.ball_in_hand || v.awaiting_decision ||
      !cue || o->cue_pocketed) {
    return out;
  }

  PlanInput next;
  next.table = ctx.in.table;
  next.physics = ctx.in.physics;
  next.step = ctx.in.step;
  next.balls = o->balls;
  next.rack = o->rack;
  const Evaluator next_eval(next, ctx.table, radToDeg(eval.judgingSigma()));
  SearchContext next_ctx{
      next, ctx.table, ctx.level, ctx.radius, next.rack.legalFirstBalls(), eval.judgingSigma()};
  std::vector<Candidate> pots = plainPots(next_ctx, next.balls, cue->pos, ctx.level.lookahead_lines,
                                          ctx.level.lookahead_speeds, ctx.level.lookahead_tips);
  assignCalls(next_ctx, pots);
  double best = 0.0;
  for (const Candidate& p : pots) {
    // The pots come easiest line first, and none can be worth more than its line's chance.
    if (p.prior <= best) break;
    const double worth = next_eval.value(p);
    ++out.simulations;
    if (worth < kContinueBase) continue;
    const double leave =
        worth >= 1.0 ? 1.0 : kPotShare + kLeaveShare * (worth - kContinueBase) / kContinueSpread;
    best = std::max(best, p.prior * leave);
  }
  out.value = kContinueBase + kContinueSpread * best;
  return out;
}

}  // namespace nineball::ai
