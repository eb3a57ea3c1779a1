#include "ai/planner_candidates.hpp"

#include <algorithm>
#include <cmath>

#include "ai/planner_geometry.hpp"
#include "ai/planner_jump.hpp"
#include "ai/planner_throw.hpp"
#include "nineball/games.hpp"
#include "nineball/snooker_rack.hpp"
#include "play/aim_guide.hpp"
#include "rules/snooker_balls.hpp"

namespace nineball::ai {
namespace {

// The fastest shot the planner plays other than the break (m/s).
constexpr double kMaxSpeed = 8.0;
// A rolling ball keeps 5/7 of a stun ball's speed: the margin on every speed estimate.
constexpr double kSlideLoss = 1.4;
// Extra speed (m/s) the object ball should still have at the pocket.
constexpr double kArrivalSpeed = 0.15;
// Safeties send the ball on at most this far either side of the line of centres.
constexpr double kSafetySpread = degToRad(70.0);
// Kicks aim at the ball on's centre and this far (in R) either side of it.
constexpr double kKickOffsetOfRadius = 0.8;
// A pocket this close (m) to a rail line is on that rail: no bank off it.
constexpr double kPocketOnRail = 0.1;
// Combinations and banks are harder than they look from the geometry.
constexpr double kCombinationDiscount = 0.5;
constexpr double kBankDiscount = 0.4;
constexpr int kMaxCombinationLines = 6;
constexpr int kMaxBankLines = 4;
// A jump pot's chance is the pot's, halved for the jump (the landing, the hop after it).
constexpr double kJumpDiscount = 0.5;
constexpr int kMaxJumpLines = 4;
// Priors of shots that do not mean to pot.
constexpr double kSafetyPrior = 0.05;
constexpr double kKickPrior = 0.01;
constexpr double kJumpHitPrior = 0.01;
const double kKickSpeeds[] = {1.2, 2.0, 3.2};
const double kBlindSpeeds[] = {1.5, 3.0};
constexpr int kBlindHeadings = 36;
const double kSweepSpeeds[] = {1.0, 2.0, 3.5};
// A push-out only has to leave the cue ball somewhere: soft, so that it is where it stops.
const double kPushOutSpeeds[] = {0.6, 1.2, 2.0};
// Safeties and kicks are tried at the level's angles on this many targets (the nearest the cue
// ball); a level with group sense shares the same number of lines among all of them, never
// fewer than the minimum each, so that a safety can use any ball of the group.
constexpr int kSafetyTargets = 2;
constexpr int kMinSafetyAnglesEach = 3;

/// A direction to strike in, before speeds and tips are chosen.
struct Line {
  ShotKind kind = ShotKind::Safety;
  double heading = 0.0;
  int target = 0;
  std::optional<PocketId> pocket;
  double prior = 0.0;
  double min_speed = 0.0;
  // Lines that mean to send the first ball hit somewhere: that ball, and where to. The aim
  // then allows for squirt and throw at each speed and tip.
  const BallState* object = nullptr;
  Vec2 send_to;
  int first = 0;  // the ball meant to be hit first
  // A jump's: how far along the line the cue ball must be down again (the ball on's contact).
  double land_by = 0.0;
};

double decel(const PhysicsParams& p) {
  return std::max(p.rolling_friction * p.gravity, 0.05);
}

// The speed a striking ball needs to give the ball it hits `object_speed` after a cut, having
// rolled `to_ghost` first, with a margin.
double strikerSpeed(const PhysicsParams& p, double object_speed, double to_ghost, double cut) {
  const double share = std::max(std::cos(cut) * (1.0 + p.ball_restitution) / 2.0, 0.15);
  const double at_contact = object_speed / share;
  return kSlideLoss * std::sqrt(at_contact * at_contact + 2.0 * decel(p) * to_ghost);
}

// The cue speed that gets the object ball `to_target` further after a cut.
double minPotSpeed(const PhysicsParams& p, double to_ghost, double to_target, double cut) {
  const double object = kSlideLoss * std::sqrt(2.0 * decel(p) * to_target) + kArrivalSpeed;
  return strikerSpeed(p, object, to_ghost, cut);
}

bool hitsFirst(const SearchContext& ctx, const std::vector<BallState>& balls, Vec2 cue,
               double heading, int id) {
  const AimGuide g = computeAimGuide(ctx.table, ctx.radius, balls, cue, heading);
  return g.target == AimTarget::Ball && g.ball == id;
}

bool meetsCushionFirst(const SearchContext& ctx, const std::vector<BallState>& balls, Vec2 cue,
                       double heading) {
  return computeAimGuide(ctx.table, ctx.radius, balls, cue, heading).target == AimTarget::Cushion;
}

double headingTo(Vec2 from, Vec2 to) {
  return std::atan2(to.y - from.y, to.x - from.x);
}

std::vector<double> aimsAcross(int count) {
  if (count <= 1) return {0.0};
  std::vector<double> out;
  for (int i = 0; i < count; ++i) out.push_back(-1.0 + 2.0 * i / (count - 1));
  return out;
}

void keepBest(std::vector<Line>& lines, int count) {
  std::stable_sort(lines.begin(), lines.end(),
                   [](const Line& a, const Line& b) { return a.prior > b.prior; });
  if (static_cast<int>(lines.size()) > count) lines.resize(static_cast<std::size_t>(count));
}

// Every pot of `on`, unranked.
std::vector<Line> potLines(const SearchContext& ctx, const std::vector<BallState>& balls, Vec2 cue,
                           const BallState& on, std::optional<PocketId> only) {
  const double sigma = ctx.prior_sigma;
  std::vector<Line> lines;
  for (const Pocket& pocket : ctx.table.pockets) {
    if (only && pocket.id != *only) continue;
    for (double across : aimsAcross(only ? 1 : ctx.level.pocket_aims)) {
      const auto g = ghostLine(cue, on.pos, pocketAim(pocket, across, ctx.radius), ctx.radius);
      if (!g || !entersPocket(pocket, g->object_dir)) continue;
      if (!pathClear(on.pos, g->target, ctx.radius, balls, kCueBall, on.id)) continue;
      if (!hitsFirst(ctx, balls, cue, g->heading, on.id)) continue;
      lines.push_back(
          {ShotKind::Pot, g->heading, on.id, pocket.id, potChance(*g, pocket, ctx.radius, sigma),
           minPotSpeed(ctx.in.physics, g->to_ghost, g->to_target, g->cut), &on, g->target, on.id});
    }
  }
  return lines;
}

// The ball on into another ball, which drops.
std::vector<Line> combinationLines(const SearchContext& ctx, const std::vector<BallState>& balls,
                                   Vec2 cue, const BallState& on) {
  const double sigma = degToRad(kReferenceAimDeg);
  std::vector<Line> lines;
  for (const BallState& second : balls) {
    if (second.pocket || second.id == kCueBall || second.id == on.id) continue;
    for (const Pocket& pocket : ctx.table.pockets) {
      const auto g2 = ghostLine(on.pos, second.pos, pocketAim(pocket, 0.0, ctx.radius), ctx.radius);
      if (!g2 || !entersPocket(pocket, g2->object_dir)) continue;
      if (!pathClear(second.pos, g2->target, ctx.radius, balls, kCueBall, second.id)) continue;
      if (!pathClear(on.pos, g2->ghost, ctx.radius, balls, on.id, second.id)) continue;
      const auto g1 = ghostLine(cue, on.pos, g2->ghost, ctx.radius);
      if (!g1 || !hitsFirst(ctx, balls, cue, g1->heading, on.id)) continue;
      const double prior = kCombinationDiscount * potChance(*g2, pocket, ctx.radius, sigma) *
                           std::erf(std::cos(g1->cut) * ctx.radius / (g1->to_ghost * sigma));
      const double on_speed = minPotSpeed(ctx.in.physics, g2->to_ghost, g2->to_target, g2->cut);
      lines.push_back({ShotKind::Combination, g1->heading, second.id, pocket.id, prior,
                       strikerSpeed(ctx.in.physics, on_speed, g1->to_ghost, g1->cut), &on,
                       g2->ghost, on.id});
    }
  }
  keepBest(lines, kMaxCombinationLines);
  return lines;
}

// The ball on off one cushion into a pocket.
std::vector<Line> bankLines(const SearchContext& ctx, const std::vector<BallState>& balls, Vec2 cue,
                            const BallState& on) {
  const double sigma = degToRad(kReferenceAimDeg);
  const double e = ctx.in.physics.cushion_restitution;
  std::vector<Line> lines;
  for (int r = 0; r < kRailCount; ++r) {
    const RailLine rail = railLine(r, ctx.table.def, ctx.radius);
    for (const Pocket& pocket : ctx.table.pockets) {
      const Vec2 aim = pocketAim(pocket, 0.0, ctx.radius);
      if (rail.offset - dot(rail.normal, aim) < kPocketOnRail) continue;
      const Vec2 image = mirrorAcross(rail, aim, e);
      const auto hit = railCrossing(rail, on.pos, image);
      if (!hit) continue;
      if (!entersPocket(pocket, bounced(rail, normalized(image - on.pos), e))) continue;
      if (!pathClear(on.pos, *hit, ctx.radius, balls, kCueBall, on.id) ||
          !pathClear(*hit, aim, ctx.radius, balls, kCueBall, on.id)) {
        continue;
      }
      const auto g = ghostLine(cue, on.pos, image, ctx.radius);
      if (!g || !hitsFirst(ctx, balls, cue, g->heading, on.id)) continue;
      lines.push_back({ShotKind::Bank, g->heading, on.id, pocket.id,
                       kBankDiscount * potChance(*g, pocket, ctx.radius, sigma),
                       minPotSpeed(ctx.in.physics, g->to_ghost, g->to_target, g->cut), &on, image,
                       on.id});
    }
  }
  keepBest(lines, kMaxBankLines);
  return lines;
}

// Pots of `on` whose cue-ball line another ball blocks: the ghost line, to be jumped.
std::vector<Line> blockedPotLines(const SearchContext& ctx, const std::vector<BallState>& balls,
                                  Vec2 cue, const BallState& on) {
  const double sigma = ctx.prior_sigma;
  std::vector<Line> lines;
  for (const Pocket& pocket : ctx.table.pockets) {
    const auto g = ghostLine(cue, on.pos, pocketAim(pocket, 0.0, ctx.radius), ctx.radius);
    if (!g || !entersPocket(pocket, g->object_dir)) continue;
    if (!pathClear(on.pos, g->target, ctx.radius, balls, kCueBall, on.id)) continue;
    if (hitsFirst(ctx, balls, cue, g->heading, on.id)) continue;
    Line line{ShotKind::Jump,
              g->heading,
              on.id,
              pocket.id,
              kJumpDiscount * potChance(*g, pocket, ctx.radius, sigma),
              0.0,
              &on,
              g->target,
              on.id};
    line.land_by = g->to_ghost;
    lines.push_back(line);
  }
  return lines;
}

// The ball on hit full and either side when no straight line reaches it: to be jumped.
std::vector<Line> blockedHitLines(const SearchContext& ctx, const std::vector<BallState>& balls,
                                  Vec2 cue, const BallState& on) {
  std::vector<Line> lines;
  const Vec2 side = perp(normalized(on.pos - cue)) * (kKickOffsetOfRadius * ctx.radius);
  for (Vec2 offset : {Vec2{}, side, -side}) {
    const Vec2 aim = on.pos + offset;
    const double heading = headingTo(cue, aim);
    if (hitsFirst(ctx, balls, cue, heading, on.id)) continue;
    Line line{ShotKind::Jump, heading, on.id, std::nullopt, kJumpHitPrior, 0.0, nullptr, {}, on.id};
    line.land_by = length(aim - cue) - 2.0 * ctx.radius;
    lines.push_back(line);
  }
  return lines;
}

std::vector<Line> safetyLines(const SearchContext& ctx, const std::vector<BallState>& balls,
                              Vec2 cue, const BallState& on, int n) {
  std::vector<Line> lines;
  const Vec2 along = normalized(on.pos - cue);
  for (int i = 0; i < n; ++i) {
    const double spread = n == 1 ? 0.0 : -kSafetySpread + 2.0 * kSafetySpread * i / (n - 1);
    const Vec2 ghost = on.pos - rotated(along, spread) * (2.0 * ctx.radius);
    const double heading = headingTo(cue, ghost);
    if (!hitsFirst(ctx, balls, cue, heading, on.id)) continue;
    lines.push_back(
        {ShotKind::Safety, heading, on.id, std::nullopt, kSafetyPrior, 0.0, nullptr, {}, on.id});
  }
  return lines;
}

// The cue ball off one cushion (or two, when the level kicks) to the ball on.
std::vector<Line> kickLines(const SearchContext& ctx, const std::vector<BallState>& balls, Vec2 cue,
                            const BallState& on) {
  const double e = ctx.in.physics.cushion_restitution;
  std::vector<Line> lines;
  auto add = [&](Vec2 image) {
    const double heading = headingTo(cue, image);
    if (meetsCushionFirst(ctx, balls, cue, heading)) {
      lines.push_back(
          {ShotKind::Kick, heading, on.id, std::nullopt, kKickPrior, 0.0, nullptr, {}, on.id});
    }
  };
  for (int r = 0; r < kRailCount; ++r) {
    const RailLine rail = railLine(r, ctx.table.def, ctx.radius);
    const Vec2 side = perp(rail.normal) * (kKickOffsetOfRadius * ctx.radius);
    for (Vec2 offset : {Vec2{}, side, -side}) add(mirrorAcross(rail, on.pos + offset, e));
  }
  if (!ctx.level.kicks) return lines;
  for (int first = 0; first < kRailCount; ++first) {
    for (int second = 0; second < kRailCount; ++second) {
      if (first == second) continue;
      const RailLine a = railLine(first, ctx.table.def, ctx.radius);
      const RailLine b = railLine(second, ctx.table.def, ctx.radius);
      add(mirrorAcross(a, mirrorAcross(b, on.pos, e), e));
    }
  }
  return lines;
}

std::vector<double> speedsFor(const std::vector<double>& choices, double min_speed) {
  std::vector<double> out;
  for (double s : choices) {
    if (s >= min_speed && s <= kMaxSpeed) out.push_back(s);
  }
  if (out.empty() && min_speed <= kMaxSpeed) out.push_back(std::min(1.2 * min_speed, kMaxSpeed));
  return out;
}

// The ghost ball's heading, or the one that allows for squirt and throw when the line means
// to send a ball somewhere.
double aimedHeading(const SearchContext& ctx, const Line& line, Vec2 cue, const Shot& shot) {
  if (!line.object) return line.heading;
  const double standard = ctx.in.physics.ball_mass;
  ThrowSetup s;
  s.cue = cue;
  s.cue_mass = standard;
  for (const BallState& b : ctx.in.balls) {
    if (b.id == kCueBall) s.cue_mass = b.mass.value_or(standard);
  }
  s.object = line.object->pos;
  s.object_mass = line.object->mass.value_or(standard);
  s.shot = shot;
  const Vec2 want = line.send_to - line.object->pos;
  return headingAllowingForThrow(ctx.in.physics, s, line.heading, std::atan2(want.y, want.x));
}

// The line's candidate struck with `shot` (placing the cue ball at `placed` first, when set).
Candidate candidateOf(const Line& line, const Shot& shot, std::optional<Vec2> placed) {
  Candidate c;
  c.kind = line.kind;
  c.shot = shot;
  c.cue = placed;
  c.target = line.target;
  c.pocket = line.pocket;
  c.first = line.first;
  c.prior = line.prior;
  return c;
}

void expand(const SearchContext& ctx, Vec2 cue, const std::vector<Line>& lines,
            const std::vector<double>& speeds, const std::vector<Vec2>& tips,
            std::optional<Vec2> placed, std::vector<Candidate>& out) {
  for (const Line& line : lines) {
    for (double speed : speedsFor(speeds, line.min_speed)) {
      for (Vec2 tip : tips) {
        Shot shot;
        shot.heading_rad = line.heading;
        shot.speed = speed;
        shot.tip = tip;
        shot.heading_rad = aimedHeading(ctx, line, cue, shot);
        out.push_back(candidateOf(line, shot, placed));
      }
    }
  }
}

// Jump lines struck at each elevation's softest speed that clears the balls in the way and comes
// down before the ball on.
void expandJumps(const SearchContext& ctx, const std::vector<BallState>& balls, Vec2 cue,
                 const std::vector<Line>& lines, std::optional<Vec2> placed,
                 std::vector<Candidate>& out) {
  for (const Line& line : lines) {
    const auto blockers =
        ballsInTheWay(balls, cue, line.heading, line.land_by, ctx.radius, line.first);
    for (const JumpStroke& j :
         jumpStrokes(ctx.in.physics, cue, line.heading, blockers, line.land_by)) {
      Shot shot;
      shot.heading_rad = line.heading;
      shot.speed = j.speed;
      shot.elevation_rad = j.elevation_rad;
      out.push_back(candidateOf(line, shot, placed));
    }
  }
}

// Whether the level jumps and the rules let it (snooker calls a jump shot a foul).
bool mayJump(const SearchContext& ctx) {
  return ctx.level.jumps && !gameDef(ctx.in.rack.game()).jump_shot_foul;
}

// The level's tips that the physics takes as a hit rather than a miscue.
std::vector<Vec2> usableTips(const SearchContext& ctx) {
  std::vector<Vec2> tips;
  for (Vec2 tip : ctx.level.tips) {
    if (length(tip) <= ctx.in.physics.miscue_limit) tips.push_back(tip);
  }
  if (tips.empty()) tips.push_back({});
  return tips;
}

// Kicks in `count` even steps round the cue ball, for the physics to tell which help.
std::vector<Line> everyDirection(const SearchContext& ctx, int count) {
  std::vector<Line> lines;
  for (int i = 0; i < count; ++i) {
    lines.push_back({ShotKind::Kick,
                     2.0 * kPi * i / count,
                     ctx.firstTarget(),
                     std::nullopt,
                     0.0,
                     0.0,
                     nullptr,
                     {}});
  }
  return lines;
}

// The targets on the table.
std::vector<const BallState*> targetBalls(const SearchContext& ctx,
                                          const std::vector<BallState>& balls) {
  std::vector<const BallState*> out;
  for (int id : ctx.targets) {
    if (const BallState* b = objectBall(balls, id)) out.push_back(b);
  }
  return out;
}

// The targets a level plays safe on or kicks at: all of them with group sense, else the
// kSafetyTargets nearest the cue ball.
std::vector<const BallState*> safetyTargets(const SearchContext& ctx,
                                            std::vector<const BallState*> ons, Vec2 cue) {
  if (ctx.level.group_sense || ons.size() <= static_cast<std::size_t>(kSafetyTargets)) return ons;
  std::stable_sort(ons.begin(), ons.end(), [&](const BallState* a, const BallState* b) {
    return length(a->pos - cue) < length(b->pos - cue);
  });
  ons.resize(kSafetyTargets);
  return ons;
}

// With several balls to choose from (a game of groups) the easiest lines are easier than with
// one ball on: 5 in 8 of them are kept (rounded up), so that the search costs about the same.
// Hard, in the game of groups (`ai-bench --game <it>`), with 8, 6 and 5 lines: run-outs 48, 50 and
// 59 of 100, think time median 0.23, 0.21 and 0.20 s.
int potLineCount(const LevelSettings& level, std::size_t targets) {
  return targets > 1 ? (level.max_pot_lines * 5 + 7) / 8 : level.max_pot_lines;
}

// Safety angles for each of `targets` balls (odd, so that the straight one is among them).
int safetyAnglesEach(const LevelSettings& level, std::size_t targets) {
  if (targets <= static_cast<std::size_t>(kSafetyTargets)) return level.safety_angles;
  const int each = level.safety_angles * kSafetyTargets / static_cast<int>(targets);
  return std::max(kMinSafetyAnglesEach, each | 1);
}

// Lines of one generator for every ball in `ons`, in that order.
template <typename Generate>
std::vector<Line> allLinesFor(const std::vector<const BallState*>& ons, Generate generate) {
  std::vector<Line> lines;
  for (const BallState* on : ons) {
    const std::vector<Line> more = generate(*on);
    lines.insert(lines.end(), more.begin(), more.end());
  }
  return lines;
}

// The same, the best `count` of them.
template <typename Generate>
std::vector<Line> linesFor(const std::vector<const BallState*>& ons, int count, Generate generate) {
  std::vector<Line> lines = allLinesFor(ons, generate);
  keepBest(lines, count);
  return lines;
}

}  // namespace

std::vector<Candidate> shotsFrom(const SearchContext& ctx, const std::vector<BallState>& balls,
                                 Vec2 cue, std::optional<Vec2> placed) {
  std::vector<Candidate> out;
  const std::vector<const BallState*> ons = targetBalls(ctx, balls);
  const std::vector<const BallState*> safe_ons = safetyTargets(ctx, ons, cue);
  const LevelSettings& level = ctx.level;
  const std::vector<Vec2> centre{Vec2{}};
  if (!ons.empty()) {
    // Snooker too: spending the budget on the best line of each ball and pocket first (fewer
    // aims across one mouth) made master's breaks worse, mean 14.7 and highest 57 against 26.8
    // and 115 over the same 8 frames (docs/ai.md, "Snooker").
    const auto pots = linesFor(ons, potLineCount(level, ons.size()), [&](const BallState& on) {
      return potLines(ctx, balls, cue, on, std::nullopt);
    });
    expand(ctx, cue, pots, level.pot_speeds, usableTips(ctx), placed, out);
    if (level.combinations) {
      const auto combinations = linesFor(ons, kMaxCombinationLines, [&](const BallState& on) {
        return combinationLines(ctx, balls, cue, on);
      });
      expand(ctx, cue, combinations, level.pot_speeds, centre, placed, out);
    }
    if (level.banks) {
      const auto banks = linesFor(
          ons, kMaxBankLines, [&](const BallState& on) { return bankLines(ctx, balls, cue, on); });
      expand(ctx, cue, banks, level.pot_speeds, centre, placed, out);
    }
    if (mayJump(ctx)) {
      const auto jumps = linesFor(ons, kMaxJumpLines, [&](const BallState& on) {
        return blockedPotLines(ctx, balls, cue, on);
      });
      expandJumps(ctx, balls, cue, jumps, placed, out);
    }
    const int angles = safetyAnglesEach(level, safe_ons.size());
    const auto safeties = allLinesFor(
        safe_ons, [&](const BallState& on) { return safetyLines(ctx, balls, cue, on, angles); });
    expand(ctx, cue, safeties, level.safety_speeds, centre, placed, out);
    if (pots.empty() && safeties.empty()) {
      const std::vector<double> kick_speeds(std::begin(kKickSpeeds), std::end(kKickSpeeds));
      const auto kicks = allLinesFor(
          safe_ons, [&](const BallState& on) { return kickLines(ctx, balls, cue, on); });
      expand(ctx, cue, kicks, kick_speeds, centre, placed, out);
      if (mayJump(ctx)) {
        const auto hits = allLinesFor(
            safe_ons, [&](const BallState& on) { return blockedHitLines(ctx, balls, cue, on); });
        expandJumps(ctx, balls, cue, hits, placed, out);
      }
    }
  }
  if (out.empty()) {
    // Nothing aims anywhere useful: try every direction and let the physics tell.
    const std::vector<double> speeds(std::begin(kBlindSpeeds), std::end(kBlindSpeeds));
    expand(ctx, cue, everyDirection(ctx, kBlindHeadings), speeds, centre, placed, out);
  }
  return out;
}

std::vector<Candidate> sweepShots(const SearchContext& ctx, int headings) {
  const std::vector<Line> lines = everyDirection(ctx, headings);
  std::vector<Candidate> out;
  const std::vector<double> speeds(std::begin(kSweepSpeeds), std::end(kSweepSpeeds));
  const BallState* cue = findOnTable(ctx.in.balls, kCueBall);
  expand(ctx, cue ? cue->pos : Vec2{}, lines, speeds, {Vec2{}}, std::nullopt, out);
  return out;
}

std::vector<Candidate> potsInto(const SearchContext& ctx, const std::vector<BallState>& balls,
                                Vec2 cue, int ball, PocketId pocket, std::optional<Vec2> placed) {
  std::vector<Candidate> out;
  if (const BallState* on = objectBall(balls, ball)) {
    std::vector<Line> lines = potLines(ctx, balls, cue, *on, pocket);
    keepBest(lines, ctx.level.max_pot_lines);
    expand(ctx, cue, lines, ctx.level.pot_speeds, usableTips(ctx), placed, out);
  }
  return out;
}

std::vector<Candidate> plainPots(const SearchContext& ctx, const std::vector<BallState>& balls,
                                 Vec2 cue, int lines, const std::vector<double>& speeds,
                                 const std::vector<Vec2>& tips) {
  std::vector<Candidate> out;
  const auto pots = linesFor(targetBalls(ctx, balls), lines, [&](const BallState& on) {
    return potLines(ctx, balls, cue, on, std::nullopt);
  });
  expand(ctx, cue, pots, speeds, tips, std::nullopt, out);
  return out;
}

std::vector<Candidate> pushOutShots(const SearchContext& ctx, int headings) {
  std::vector<Line> lines = everyDirection(ctx, headings);
  for (Line& line : lines) {
    line.kind = ShotKind::PushOut;
    line.target = 0;
  }
  std::vector<Candidate> out;
  const std::vector<double> speeds(std::begin(kPushOutSpeeds), std::end(kPushOutSpeeds));
  const BallState* cue = findOnTable(ctx.in.balls, kCueBall);
  expand(ctx, cue ? cue->pos : Vec2{}, lines, speeds, {Vec2{}}, std::nullopt, out);
  return out;
}

namespace {

// Snooker: the striker nominates the colour after a red, and the ball he plays as a free ball
// (WPBSA 3.6, 3.12); the rules take the first colour hit when none is stated, which a kiss
// on the way could make another.
bool nominates(const rules::Rack& rack) {
  return rack.game() == rules::Game::Snooker &&
         (rack.state().snooker.colour_on || rules::freeBall(rack));
}

// A call the match takes: snooker refuses a nomination its rules would not read.
bool mayCall(const rules::Rack& rack, int ball) {
  return rack.game() != rules::Game::Snooker ||
         !rules::snooker::nominationProblem(rack.state(), ball);
}

}  // namespace

void assignCalls(const SearchContext& ctx, std::vector<Candidate>& cands) {
  if (!ctx.in.rack.callRequired() && !nominates(ctx.in.rack)) return;
  for (Candidate& c : cands) {
    if (c.kind == ShotKind::PushOut) continue;
    if (c.pocket && c.target > 0 && mayCall(ctx.in.rack, c.target)) {
      c.call = rules::Call{c.target, *c.pocket};
      continue;
    }
    // A snooker stroke in no particular direction leaves the nomination to the first colour
    // it hits.
    if (c.first <= 0 && !ctx.in.rack.callRequired()) continue;
    const int ball = c.first > 0 ? c.first : ctx.firstTarget();
    const BallState* b = objectBall(ctx.in.balls, ball);
    if (!b || !mayCall(ctx.in.rack, ball)) continue;
    const Pocket* nearest = nullptr;
    for (const Pocket& p : ctx.table.pockets) {
      if (!nearest || length(p.drop_centre - b->pos) < length(nearest->drop_centre - b->pos))
        nearest = &p;
    }
    if (nearest) c.call = rules::Call{ball, nearest->id};
  }
}

}  // namespace nineball::ai
