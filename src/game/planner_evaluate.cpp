#include "game/planner_evaluate.hpp"

#include <malloc.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>

#include "game/planner_geometry.hpp"
#include "game/shot_summary.hpp"
#include "nineball/world.hpp"

namespace nineball::ai {
namespace {

// A planned shot that still rolls after this long (s) is cut short: its outcome is as good as
// known, and a pathological one must not stall the search.
constexpr double kMaxShotTime = 40.0;

constexpr double kContinueBase = 0.55;
constexpr double kContinueSpread = 0.4;
constexpr double kLeaveBase = 0.45;
constexpr double kLeaveSpread = 0.4;

// A foul nothing later in the shot can undo: the cue ball pocketed, or its first contact with
// a ball other than the ball on.
bool foulDecided(const std::vector<Event>& events, int ball_on) {
  bool first_seen = false;
  for (const Event& e : events) {
    if (e.type == EventType::Pocket && e.a == kCueBall) return true;
    if (e.type != EventType::BallBall || first_seen) continue;
    if (e.a != kCueBall && e.b != kCueBall) continue;
    first_seen = true;
    if ((e.a == kCueBall ? e.b : e.a) != ball_on) return true;
  }
  return false;
}

// The evaluator builds and frees a world for every candidate (Box2D allocates over 100 KiB for
// each). With glibc's default trim threshold of 128 KiB every free gave the heap back to the
// kernel and the next world faulted it in again: a fifth of the planner's time went to brk
// and page faults. Keeping up to 64 MiB of freed heap costs nothing else.
void keepFreedHeap() {
  static std::once_flag once;
  std::call_once(once, [] { mallopt(M_TRIM_THRESHOLD, 64 << 20); });
}

}  // namespace

Evaluator::Evaluator(const PlanInput& in, const TableGeometry& table, double judging_aim_deg)
    : in_(in), table_(table), step_(in.step), sigma_rad_(degToRad(judging_aim_deg)) {
  keepFreedHeap();
  step_.max_time = std::min(step_.max_time, kMaxShotTime);
}

std::vector<BallState> Evaluator::ballsWithCueAt(Vec2 cue) const {
  std::vector<BallState> balls;
  balls.reserve(in_.balls.size() + 1);
  BallState cue_ball;
  cue_ball.id = kCueBall;
  for (const BallState& b : in_.balls) {
    if (b.id == kCueBall) {
      cue_ball.mass = b.mass;
      continue;
    }
    if (!b.pocket) balls.push_back(b);
  }
  cue_ball.pos = cue;
  balls.insert(balls.begin(), cue_ball);
  return balls;
}

double Evaluator::value(const Shot& shot, std::optional<Vec2> cue) const {
  World world(in_.table, in_.physics, step_);
  if (cue) {
    for (const BallState& b : ballsWithCueAt(*cue)) world.addBall(b);
  } else {
    for (const BallState& b : in_.balls) {
      if (!b.pocket) world.addBall(b);
    }
  }
  world.strike(kCueBall, shot);
  // Under WPA rules a scratch or a wrong first ball is a foul whatever follows, and a foul is
  // worth the same wherever the balls stop (ball in hand): the rest of the shot is not run.
  const int ball_on = in_.rack.ballOn();
  const bool may_stop = in_.rack.rules() == rules::RuleSet::Wpa && !in_.rack.isBreak();
  world.runUntilRest(
      [&](const std::vector<Event>& events) { return may_stop && foulDecided(events, ball_on); });
  const rules::ShotSummary summary = game::summarize(world.events());
  rules::Rack rack = in_.rack;
  rules::Verdict verdict;
  try {
    verdict = rack.shoot(summary, false);
  } catch (const std::logic_error&) {
    return 0.0;  // the rules take no shot now: nothing to gain
  }
  std::vector<BallState> after = world.balls();
  for (int spotted : verdict.to_spot) {
    for (BallState& b : after) {
      if (b.id != spotted) continue;
      b.pocket.reset();
      b.pos = table_.footSpot();
    }
  }
  return score(after, rack, verdict, summary.cue_pocketed);
}

double Evaluator::score(const std::vector<BallState>& after, const rules::Rack& rack,
                        const rules::Verdict& verdict, bool cue_pocketed) const {
  const rules::Player me = in_.rack.shooter();
  if (verdict.winner) return *verdict.winner == me ? 1.0 : 0.0;
  const double r = in_.physics.ball_radius;
  auto chanceFrom = [&](Vec2 cue) {
    return bestPotChance(table_, r, after, cue, rack.ballOn(), sigma_rad_);
  };
  const BallState* cue = findOnTable(after, kCueBall);
  double chance = kInHandChance;
  if (!verdict.ball_in_hand) {
    if (cue && !cue_pocketed) {
      chance = chanceFrom(cue->pos);
    } else if (verdict.cue_to_head_spot) {
      chance = chanceFrom({table_.headStringX(), 0.0});
    }
  }
  if (verdict.next == me) return kContinueBase + kContinueSpread * chance;
  if (verdict.legal()) return kLeaveBase - kLeaveSpread * chance;
  return kFoulValueTop * (1.0 - chance);
}

}  // namespace nineball::ai
