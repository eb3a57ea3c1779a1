// Snooker's worth of a simulated shot, on the planner's scale (0 loses the frame, 1 wins it, a
// shot that keeps the table at least kContinueBase, a foul at most kFoulValueTop): break
// building. What keeps the break going comes first (the chance of potting a ball on next from
// where the cue ball stops), the points potted settle the rest (so a black is chosen over a
// yellow when the position is alike), reds left open to a pocket count while reds remain (the
// pack split), a safety is worth how little it leaves, a snooker most, and a foul by the
// penalty it gives away and what it leaves.
#include <algorithm>
#include <cmath>

#include "ai/planner_evaluate.hpp"
#include "ai/planner_geometry.hpp"
#include "nineball/table_markings.hpp"
#include "play/snookered.hpp"
#include "rules/snooker_balls.hpp"

namespace nineball::ai {
namespace {

// Per point potted: a red 0.004, a black 0.028. Small beside the next ball's chance (a tenth of
// a chance is worth 0.035): position decides, the colour's value breaks near ties.
constexpr double kPointWeight = 0.004;
// The next ball's chance weighs this much on a shot that keeps the table (pool's 0.4, less the
// room the points and the reds' spread take below 1).
constexpr double kNextChanceSpread = 0.35;
// The share of the reds open to a pocket, while reds remain: all open against all blocked or in
// the pack is worth this much to whoever is at the table (eight-ball's kGroupWeight is 0.1 for
// the same idea; less here because a split helps the striker only while he keeps the table).
constexpr double kOpenRedsWeight = 0.04;
// A leave with no ball on in a straight line (WPBSA's snookered) is worth this much more than
// its (already nil) chance says: the opponent may foul or miss.
constexpr double kSnookerBonus = 0.05;
// Fouls give away 4 to 7 points (WPBSA 3.15): the lowest penalty and the worst leave both
// halve a foul's worth.
constexpr int kLowestPenalty = 4;
constexpr int kHighestPenalty = 7;
// A legal shot that leaves the table stays worth more than any foul.
constexpr double kLeaveFloor = kFoulValueTop + 0.005;
constexpr double kLeaveBase = 0.45;
constexpr double kLeaveSpread = 0.4;
// The cue ball in hand in the D (after an in-off): places tried, as fractions of the D's radius
// along the baulk line (y) and round its arc.
constexpr double kOnLine[] = {0.0, -0.5, 0.5, -1.0, 1.0};
constexpr double kArcDeg[] = {135.0, 180.0, 225.0};

int index(rules::Player p) {
  return p == rules::Player::A ? 0 : 1;
}

std::vector<int> redsOnTable(const rules::Rack& rack) {
  std::vector<int> reds;
  for (int id : rack.ballsOnTable()) {
    if (rules::snooker::isRed(id)) reds.push_back(id);
  }
  return reds;
}

bool fitsAt(const std::vector<BallState>& balls, Vec2 c, double radius) {
  for (const BallState& b : balls) {
    if (b.id == kCueBall || b.pocket) continue;
    if (length(b.pos - c) < 2.0 * radius) return false;
  }
  return true;
}

}  // namespace

double Evaluator::chanceFromTheD(const std::vector<BallState>& after,
                                 const rules::Rack& rack) const {
  const SnookerLayout layout = SnookerLayout::of(in_.table);
  const double x = layout.baulk_x;
  const double r = layout.d_radius;
  std::vector<Vec2> places;
  for (double f : kOnLine) places.push_back({x, f * r});
  for (double deg : kArcDeg) {
    const double a = degToRad(deg);
    places.push_back({x + r * std::cos(a), r * std::sin(a)});
  }
  double best = 0.0;
  for (Vec2 c : places) {
    if (fitsAt(after, c, in_.physics.ball_radius))
      best = std::max(best, chanceFrom(after, rack, c));
  }
  return best;
}

double Evaluator::snookerChance(const Outcome& o) const {
  const BallState* cue = findOnTable(o.balls, kCueBall);
  if (o.verdict.ball_in_hand || o.cue_pocketed || !cue) return chanceFromTheD(o.balls, o.rack);
  return chanceFrom(o.balls, o.rack, cue->pos);
}

double Evaluator::snookerScore(const Outcome& o) const {
  const rules::Verdict& verdict = o.verdict;
  const rules::Player me = in_.rack.shooter();
  if (verdict.winner) return *verdict.winner == me ? 1.0 : 0.0;
  const double chance = snookerChance(o);
  const std::vector<int> reds = redsOnTable(o.rack);
  const double radius = in_.physics.ball_radius;
  const double open_reds = reds.empty() ? 0.0 : openShare(table_, radius, o.balls, reds);
  if (verdict.legal() && verdict.next == me) {
    return kContinueBase + kNextChanceSpread * chance + kPointWeight * verdict.points[index(me)] +
           kOpenRedsWeight * open_reds;
  }
  if (verdict.legal()) {
    const BallState* cue = findOnTable(o.balls, kCueBall);
    const bool snookered =
        cue && play::snookered(cue->pos, o.rack.legalFirstBalls(), o.balls, radius);
    const double leave = kLeaveBase - kLeaveSpread * chance - kOpenRedsWeight * open_reds +
                         (snookered ? kSnookerBonus : 0.0);
    return std::max(kLeaveFloor, leave);
  }
  const int penalty =
      verdict.points[index(me == rules::Player::A ? rules::Player::B : rules::Player::A)];
  const double given = std::clamp(
      static_cast<double>(penalty - kLowestPenalty) / (kHighestPenalty - kLowestPenalty), 0.0, 1.0);
  return kFoulValueTop * (1.0 - 0.5 * chance - 0.5 * given);
}

}  // namespace nineball::ai
