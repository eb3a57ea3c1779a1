// Where the planner puts the cue ball: behind the head string for the break, and anywhere
// legal with ball in hand.
#include <algorithm>
#include <cmath>

#include "ai/planner_candidates.hpp"
#include "ai/planner_geometry.hpp"
#include "nineball/games.hpp"
#include "play/aim_guide.hpp"

namespace nineball::ai {
namespace {

// Clearance (m) kept between a placed cue ball and any other ball, beyond touching.
constexpr double kPlacementGap = 0.001;
// Break spots along the head string, in the order tried (m from the long axis). Measured on
// 30 racks a setting: from the middle at 8-9.5 m/s with a centre or slightly low tip every
// break pocketed a ball and none scratched; from 0.25 m out a quarter pocketed nothing.
// Ten-ball's tighter rack is another matter: from the middle alone 7 breaks of 30 pocketed a
// ball, choosing among all five spots 24 of 30 (`ai-bench --racks 30`, hard, in the game that sets
// GameDef::break_from_every_spot), so that game tries every spot. Another did not: its breaks
// pocketed a ball in 93 of 100 racks from the middle and in 49 choosing among the five.
const double kBreakSpots[] = {0.0, 0.12, -0.12, 0.25, -0.25};
const Vec2 kBreakTips[] = {{0.0, 0.0}, {0.0, -0.2}};
// Ball in hand: the cue ball goes this far (m) behind the ghost ball ...
const double kInHandDistances[] = {0.12, 0.25, 0.45};
// ... at these cut angles.
const double kInHandCuts[] = {0.0, 20.0, -20.0, 40.0, -40.0};
// Spacing (m) of the grid searched for a spot to play safe from, and how many spots are kept.
constexpr double kSafetyGrid = 0.12;
constexpr int kSafetySpots = 3;
// Safety spots nearer the ball on than this (m) leave too little room to play it softly.
constexpr double kSafetyMinDistance = 0.2;

struct Placement {
  Vec2 cue;
  PocketId pocket = PocketId::TopLeft;
  double prior = 0.0;
  int ball = 0;  // the ball to pot from there
};

bool legalSpot(const SearchContext& ctx, Vec2 c) {
  if (!ctx.table.ballFits(c, ctx.radius)) return false;
  if (ctx.in.behind_head_string && c.x > ctx.table.headStringX()) return false;
  if (!inCueArea(ctx.in.cue_area, ctx.table.def, c)) return false;
  for (const BallState& b : ctx.in.balls) {
    if (b.pocket || b.id == kCueBall) continue;
    if (length(b.pos - c) < 2.0 * ctx.radius + kPlacementGap) return false;
  }
  return true;
}

// Spots behind the ball on along its lines to every open pocket.
std::vector<Placement> potPlacements(const SearchContext& ctx, const Evaluator& eval,
                                     const BallState& on) {
  const double sigma = degToRad(kReferenceAimDeg);
  std::vector<Placement> spots;
  for (const Pocket& pocket : ctx.table.pockets) {
    const Vec2 target = pocketAim(pocket, 0.0, ctx.radius);
    const Vec2 u = normalized(target - on.pos);
    if (!entersPocket(pocket, u)) continue;
    if (!pathClear(on.pos, target, ctx.radius, ctx.in.balls, kCueBall, on.id)) continue;
    const Vec2 ghost = on.pos - u * (2.0 * ctx.radius);
    for (double d : kInHandDistances) {
      for (double cut : kInHandCuts) {
        const Vec2 c = ghost - rotated(u, degToRad(cut)) * d;
        if (!legalSpot(ctx, c)) continue;
        const auto balls = eval.ballsWithCueAt(c);
        const auto line = ghostLine(c, on.pos, target, ctx.radius);
        if (!line || !pathClear(c, ghost, ctx.radius, balls, kCueBall, on.id)) continue;
        spots.push_back({c, pocket.id, potChance(*line, pocket, ctx.radius, sigma), on.id});
      }
    }
  }
  return spots;
}

// The best spots, taking the pockets in turn (the easiest pocket first) so that the search
// sees different ways round the table rather than one pocket from many spots.
std::vector<Placement> spreadOverPockets(std::vector<Placement> spots, int count) {
  std::stable_sort(spots.begin(), spots.end(),
                   [](const Placement& a, const Placement& b) { return a.prior > b.prior; });
  std::vector<PocketId> order;
  for (const Placement& p : spots) {
    if (std::find(order.begin(), order.end(), p.pocket) == order.end()) order.push_back(p.pocket);
  }
  std::vector<Placement> chosen;
  std::vector<bool> used(spots.size(), false);
  while (static_cast<int>(chosen.size()) < count && chosen.size() < spots.size()) {
    for (PocketId pocket : order) {
      for (std::size_t i = 0; i < spots.size(); ++i) {
        if (used[i] || spots[i].pocket != pocket) continue;
        used[i] = true;
        chosen.push_back(spots[i]);
        break;
      }
      if (static_cast<int>(chosen.size()) >= count) break;
    }
  }
  return chosen;
}

// Spots with a clear line to the ball on, to play safe from when nothing can be potted.
std::vector<Vec2> safetySpots(const SearchContext& ctx, const Evaluator& eval,
                              const BallState& on) {
  std::vector<std::pair<double, Vec2>> found;
  const double hx = ctx.table.def.length / 2.0, hy = ctx.table.def.width / 2.0;
  for (double x = -hx + kSafetyGrid / 2.0; x < hx; x += kSafetyGrid) {
    for (double y = -hy + kSafetyGrid / 2.0; y < hy; y += kSafetyGrid) {
      const Vec2 c{x, y};
      const double d = length(on.pos - c);
      if (d < kSafetyMinDistance || !legalSpot(ctx, c)) continue;
      const auto guide = computeAimGuide(ctx.table, ctx.radius, eval.ballsWithCueAt(c), c,
                                         std::atan2(on.pos.y - y, on.pos.x - x));
      if (guide.target == AimTarget::Ball && guide.ball == on.id) found.push_back({d, c});
    }
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Vec2> spots;
  for (const auto& f : found) {
    if (static_cast<int>(spots.size()) >= kSafetySpots) break;
    spots.push_back(f.second);
  }
  return spots;
}

// Any legal spot at all, nearest the head spot first: the last resort.
Vec2 anyLegalSpot(const SearchContext& ctx) {
  const Vec2 head{ctx.table.headStringX(), 0.0};
  for (double r = 0.0; r < ctx.table.def.length; r += ctx.radius) {
    for (int k = 0; k < 16; ++k) {
      const Vec2 c = head + fromAngle(2.0 * kPi * k / 16.0) * r;
      if (legalSpot(ctx, c)) return c;
    }
  }
  return head;
}

// The rack's apex: the object ball nearest the head string on the long axis (nine- and
// rack whose apex ball must be hit first, the ball there).
const BallState* apexBall(const SearchContext& ctx) {
  const Vec2 head{ctx.table.headStringX(), 0.0};
  const BallState* apex = nullptr;
  for (const BallState& b : ctx.in.balls) {
    if (b.pocket || b.id == kCueBall) continue;
    if (!apex || length(b.pos - head) < length(apex->pos - head)) apex = &b;
  }
  return apex;
}

}  // namespace

std::vector<Candidate> breakShots(const SearchContext& ctx, const Evaluator& eval) {
  std::vector<Candidate> out;
  const BallState* on = apexBall(ctx);
  const bool every_spot = gameDef(ctx.in.rack.game()).break_from_every_spot;
  const int spots = every_spot ? static_cast<int>(std::size(kBreakSpots))
                               : std::min<int>(ctx.level.break_spots, std::size(kBreakSpots));
  for (int i = 0; i < spots; ++i) {
    const Vec2 c{ctx.table.headStringX(), kBreakSpots[i]};
    if (!legalSpot(ctx, c)) continue;
    const Vec2 aim = on ? on->pos : ctx.table.footSpot();
    for (double speed : ctx.level.break_speeds) {
      for (Vec2 tip : kBreakTips) {
        if (length(tip) > ctx.in.physics.miscue_limit) continue;
        Candidate cand;
        cand.kind = ShotKind::Break;
        cand.shot.heading_rad = std::atan2(aim.y - c.y, aim.x - c.x);
        cand.shot.speed = speed;
        cand.shot.tip = tip;
        cand.cue = c;
        cand.target = on ? on->id : 0;
        cand.first = cand.target;
        out.push_back(cand);
      }
    }
  }
  if (out.empty()) {
    const Vec2 c = anyLegalSpot(ctx);
    return shotsFrom(ctx, eval.ballsWithCueAt(c), c, c);
  }
  return out;
}

std::vector<Candidate> inHandShots(const SearchContext& ctx, const Evaluator& eval) {
  std::vector<Candidate> out;
  std::vector<Placement> spots;
  for (int id : ctx.targets) {
    if (const BallState* b = objectBall(ctx.in.balls, id)) {
      const auto more = potPlacements(ctx, eval, *b);
      spots.insert(spots.end(), more.begin(), more.end());
    }
  }
  for (const Placement& p : spreadOverPockets(spots, ctx.level.placements)) {
    const auto shots = potsInto(ctx, eval.ballsWithCueAt(p.cue), p.cue, p.ball, p.pocket, p.cue);
    out.insert(out.end(), shots.begin(), shots.end());
  }
  // With nothing to pot, play safe on the lowest target from a spot near it.
  if (const BallState* on = objectBall(ctx.in.balls, ctx.firstTarget())) {
    if (out.empty()) {
      for (Vec2 c : safetySpots(ctx, eval, *on)) {
        const auto shots = shotsFrom(ctx, eval.ballsWithCueAt(c), c, c);
        out.insert(out.end(), shots.begin(), shots.end());
      }
    }
  }
  if (out.empty()) {
    const Vec2 c = anyLegalSpot(ctx);
    return shotsFrom(ctx, eval.ballsWithCueAt(c), c, c);
  }
  return out;
}

}  // namespace nineball::ai
