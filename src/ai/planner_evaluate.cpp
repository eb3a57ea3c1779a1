#include "ai/planner_evaluate.hpp"

#include <malloc.h>

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <stdexcept>

#include "ai/planner_geometry.hpp"
#include "ai/thread_world.hpp"
#include "nineball/engine.hpp"
#include "nineball/games.hpp"
#include "play/shot_summary.hpp"

namespace nineball::ai {
namespace {

// A planned shot that still rolls after this long (s) is cut short: its outcome is as good as
// known, and a pathological one must not stall the search.
constexpr double kPlanningHorizon = 40.0;

constexpr double kLeaveBase = 0.45;
constexpr double kLeaveSpread = 0.4;
// A position worth this to whoever shoots from it when the chance of a pot there is c:
// a pot keeps the table (about 0.75), a miss gives it away (about 0.25).
constexpr double kShooterBase = 0.25;
constexpr double kShooterSpread = 0.5;

// Eight-ball: how much the balls of each group still open to a pocket weigh in a position
// (one group all open and the other all blocked or clustered is worth this much either way).
// Small beside a pot's worth: it settles the choice among shots the rest scores alike, which
// group to take, where to leave blockers, which cluster to open.
constexpr double kGroupWeight = 0.1;
// A legal shot that leaves the table stays worth more than any foul.
constexpr double kLeaveFloor = kFoulValueTop + 0.005;

bool contains(const std::vector<int>& v, int x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

// A foul nothing later in the shot can undo: the cue ball pocketed, or (unless `any_first`,
// as on a push-out) its first contact with a ball it may not hit first.
bool foulDecided(const std::vector<Event>& events, const std::vector<int>& legal_first,
                 bool any_first) {
  bool first_seen = false;
  for (const Event& e : events) {
    if (e.type == EventType::Pocket && e.a == kCueBall) return true;
    if (any_first || e.type != EventType::BallBall || first_seen) continue;
    if (e.a != kCueBall && e.b != kCueBall) continue;
    first_seen = true;
    if (!contains(legal_first, e.a == kCueBall ? e.b : e.a)) return true;
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

Evaluator::Evaluator(const PlanInput& in, const TableGeometry& table, double judging_aim_deg,
                     bool group_sense)
    : in_(in),
      table_(table),
      step_(in.step),
      sigma_rad_(degToRad(judging_aim_deg)),
      group_sense_(group_sense),
      legal_first_(in.rack.legalFirstBalls()) {
  keepFreedHeap();
  step_.max_time = std::min(step_.max_time, kPlanningHorizon);
  // The exact engine is also the faster one; it agrees with the Box2D engine to the suite's
  // 1 mm, far inside the noise the planner judges its shots under.
  step_.engine = EngineKind::named("reference");
  id_ = newWorldOwner();
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

Engine& Evaluator::engineForThisThread() const {
  return worldForThisThread(id_, in_.table, in_.physics, step_);
}

std::optional<Outcome> Evaluator::outcome(const Candidate& c, const Shot& shot) const {
  Engine& world = engineForThisThread();
  if (c.cue) {
    for (const BallState& b : ballsWithCueAt(*c.cue)) world.addBall(b);
  } else {
    for (const BallState& b : in_.balls) {
      if (!b.pocket) world.addBall(b);
    }
  }
  world.strike(kCueBall, shot);
  // Under WPA rules a scratch or a wrong first ball is a foul whatever follows, and a foul is
  // worth the same wherever the balls stop (ball in hand): the rest of the shot is not run.
  const bool push_out = c.kind == ShotKind::PushOut;
  const bool may_stop = in_.rack.rules() == rules::RuleSet::Wpa && !in_.rack.isBreak();
  world.runUntilRest([&](const std::vector<Event>& events) {
    return may_stop && foulDecided(events, legal_first_, push_out);
  });
  rules::ShotSummary summary = play::summarize(world.events());
  summary.call = c.call;
  Outcome o{{}, in_.rack, {}, summary.cue_pocketed};
  try {
    o.verdict = o.rack.shoot(summary, push_out);
  } catch (const std::logic_error&) {
    return std::nullopt;
  }
  o.balls = world.balls();
  respotBalls(o);
  return o;
}

void Evaluator::respotBalls(Outcome& o) const {
  const SpotFinder finder = gameDef(in_.rack.game()).spot;
  std::vector<int> to_spot = o.verdict.to_spot;
  // WPBSA 3.7(b): when several colours are spotted the highest value takes precedence (the
  // order src/play/match.cpp spots them in).
  if (finder) std::sort(to_spot.rbegin(), to_spot.rend());
  for (int spotted : to_spot) {
    const Vec2 place =
        finder ? finder(spotted, table_, in_.physics.ball_radius, o.balls) : table_.footSpot();
    for (BallState& b : o.balls) {
      if (b.id != spotted) continue;
      b.backOnTable();
      b.pos = place;
    }
  }
}

double Evaluator::value(const Candidate& c, const Shot& shot) const {
  const std::optional<Outcome> o = outcome(c, shot);
  return o ? score(*o) : 0.0;  // the rules take no shot now: nothing to gain
}

double Evaluator::chanceFrom(const std::vector<BallState>& after, const rules::Rack& rack,
                             Vec2 cue) const {
  double best = 0.0;
  for (int ball : rack.legalFirstBalls()) {
    best = std::max(best,
                    bestPotChance(table_, in_.physics.ball_radius, after, cue, ball, sigma_rad_));
  }
  return best;
}

double Evaluator::groupBalance(const Outcome& o) const {
  if (!group_sense_ || o.rack.game() != rules::Game::EightBall) return 0.0;
  const rules::Player me = in_.rack.shooter();
  const std::optional<rules::Group> mine = o.rack.groups().of(me);
  if (!mine) return 0.0;
  std::vector<int> my_balls;
  std::vector<int> their_balls;
  for (int id = 1; id <= 15; ++id) {
    const std::optional<rules::Group> g = rules::groupOf(id);
    if (g) (*g == *mine ? my_balls : their_balls).push_back(id);
  }
  const double r = in_.physics.ball_radius;
  return kGroupWeight *
         (openShare(table_, r, o.balls, my_balls) - openShare(table_, r, o.balls, their_balls));
}

double Evaluator::score(const Outcome& o) const {
  if (in_.rack.game() == rules::Game::Snooker) return snookerScore(o);
  const rules::Verdict& verdict = o.verdict;
  const rules::Player me = in_.rack.shooter();
  if (verdict.winner) return *verdict.winner == me ? 1.0 : 0.0;
  const BallState* cue = findOnTable(o.balls, kCueBall);
  double chance = kInHandChance;
  if (!verdict.ball_in_hand) {
    if (cue && !o.cue_pocketed) {
      chance = chanceFrom(o.balls, o.rack, cue->pos);
    } else if (verdict.cue_to_head_spot) {
      chance = chanceFrom(o.balls, o.rack, {table_.headStringX(), 0.0});
    }
  }
  if (verdict.next == me) return kContinueBase + kContinueSpread * chance + groupBalance(o);
  if (verdict.legal() && verdict.decision == rules::Decision::PlayOrPass) {
    const double shooter = kShooterBase + kShooterSpread * chance;
    return std::min(shooter, 1.0 - shooter);
  }
  if (verdict.legal()) {
    return std::max(kLeaveFloor, kLeaveBase - kLeaveSpread * chance + groupBalance(o));
  }
  return kFoulValueTop * (1.0 - chance);
}

}  // namespace nineball::ai
