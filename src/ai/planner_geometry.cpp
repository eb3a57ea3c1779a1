#include "ai/planner_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::ai {
namespace {

// Cuts thinner than this are not tried: the object ball barely moves and the aim is hopeless.
constexpr double kMaxCut = degToRad(80.0);
// How steeply a ball may meet a mouth (from the pocket's axis) and still drop: corners take a
// ball running along the rail (45 degrees); side pockets reject shallow angles.
constexpr double kCornerEntry = degToRad(62.0);
constexpr double kSideEntry = degToRad(55.0);
// The part of the mouth the aim points span, as a fraction of the half-mouth.
constexpr double kAcrossSpan = 0.45;
// Aim a little past the mouth line, into the pocket.
constexpr double kAimDepthOfRadius = 0.5;

bool isSide(const Pocket& p) {
  return p.id == PocketId::TopSide || p.id == PocketId::BottomSide;
}

}  // namespace

Vec2 pocketAim(const Pocket& pocket, double across, double radius) {
  const Vec2 mid = (pocket.jaw_a + pocket.jaw_b) * 0.5;
  const Vec2 half = (pocket.jaw_b - pocket.jaw_a) * 0.5;
  return mid + half * (kAcrossSpan * across) + pocket.outward * (kAimDepthOfRadius * radius);
}

bool entersPocket(const Pocket& pocket, Vec2 dir) {
  const double c = std::clamp(dot(normalized(dir), pocket.outward), -1.0, 1.0);
  return std::acos(c) <= (isSide(pocket) ? kSideEntry : kCornerEntry);
}

bool pathClear(Vec2 a, Vec2 b, double radius, const std::vector<BallState>& balls, int skip_a,
               int skip_b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double reach = 2.0 * radius;
  for (const BallState& o : balls) {
    if (o.pocket || o.id == skip_a || o.id == skip_b) continue;
    const double t = len2 > 0.0 ? std::clamp(dot(o.pos - a, ab) / len2, 0.0, 1.0) : 0.0;
    const Vec2 d = o.pos - (a + ab * t);
    if (dot(d, d) < reach * reach) return false;
  }
  return true;
}

std::optional<GhostLine> ghostLine(Vec2 cue, Vec2 object, Vec2 target, double radius) {
  GhostLine g;
  g.target = target;
  const Vec2 to_target = target - object;
  g.to_target = length(to_target);
  if (g.to_target <= 0.0) return std::nullopt;
  const Vec2 u = to_target / g.to_target;
  g.object_dir = u;
  g.ghost = object - u * (2.0 * radius);
  const Vec2 to_ghost = g.ghost - cue;
  g.to_ghost = length(to_ghost);
  if (g.to_ghost < 1e-6) return std::nullopt;
  const Vec2 v = to_ghost / g.to_ghost;
  g.heading = std::atan2(v.y, v.x);
  g.cut = std::acos(std::clamp(dot(u, v), -1.0, 1.0));
  if (g.cut > kMaxCut) return std::nullopt;
  return g;
}

double potChance(const GhostLine& line, const Pocket& pocket, double radius, double sigma_rad) {
  const double entry = std::acos(std::clamp(dot(line.object_dir, pocket.outward), -1.0, 1.0));
  const double mouth_half = 0.5 * length(pocket.jaw_b - pocket.jaw_a);
  // Room for the ball's centre in the mouth, narrower when the ball comes in at an angle.
  const double straight = isSide(pocket) ? 0.0 : degToRad(45.0);
  const double off_axis = std::max(0.0, entry - straight);
  const double window = std::max(0.0, (mouth_half - 0.5 * radius) * std::cos(off_axis));
  // A ghost-ball error e turns the object ball by e / (2R cos cut); the aim error at the cue
  // is e / distance to the ghost.
  const double object_room = window / std::max(line.to_target, radius);
  const double ghost_room = object_room * 2.0 * radius * std::cos(line.cut);
  const double cue_room = ghost_room / std::max(line.to_ghost, radius);
  return std::erf(cue_room / (sigma_rad * std::sqrt(2.0)));
}

double bestPotChance(const TableGeometry& table, double radius, const std::vector<BallState>& balls,
                     Vec2 cue, int ball_on, double sigma_rad) {
  const BallState* on = objectBall(balls, ball_on);
  if (!on) return 0.0;
  double best = 0.0;
  for (const Pocket& pocket : table.pockets) {
    const auto line = ghostLine(cue, on->pos, pocketAim(pocket, 0.0, radius), radius);
    if (!line || !entersPocket(pocket, line->target - on->pos)) continue;
    if (!pathClear(cue, line->ghost, radius, balls, kCueBall, ball_on)) continue;
    if (!pathClear(on->pos, line->target, radius, balls, kCueBall, ball_on)) continue;
    best = std::max(best, potChance(*line, pocket, radius, sigma_rad));
  }
  return best;
}

double openShare(const TableGeometry& table, double radius, const std::vector<BallState>& balls,
                 const std::vector<int>& ids) {
  int left = 0;
  int open = 0;
  for (int id : ids) {
    const BallState* b = objectBall(balls, id);
    if (!b) continue;
    ++left;
    for (const Pocket& pocket : table.pockets) {
      const Vec2 target = pocketAim(pocket, 0.0, radius);
      if (entersPocket(pocket, target - b->pos) &&
          pathClear(b->pos, target, radius, balls, id, kCueBall)) {
        ++open;
        break;
      }
    }
  }
  return left == 0 ? 1.0 : static_cast<double>(open) / left;
}

RailLine railLine(int rail, const TableDef& table, double radius) {
  const double hx = table.length / 2.0 - radius;
  const double hy = table.width / 2.0 - radius;
  switch (rail) {
    case 0:
      return {{1.0, 0.0}, hx, hy};
    case 1:
      return {{-1.0, 0.0}, hx, hy};
    case 2:
      return {{0.0, 1.0}, hy, hx};
    default:
      return {{0.0, -1.0}, hy, hx};
  }
}

Vec2 mirrorAcross(const RailLine& rail, Vec2 p, double restitution) {
  const double inside = rail.offset - dot(rail.normal, p);
  return p + rail.normal * (inside * (1.0 + 1.0 / std::max(restitution, 0.05)));
}

std::optional<Vec2> railCrossing(const RailLine& rail, Vec2 a, Vec2 b) {
  const double da = rail.offset - dot(rail.normal, a);
  const double db = rail.offset - dot(rail.normal, b);
  if (da <= 0.0 || db >= 0.0) return std::nullopt;
  const Vec2 hit = a + (b - a) * (da / (da - db));
  const Vec2 along = perp(rail.normal);
  if (std::abs(dot(hit, along)) > rail.half_span) return std::nullopt;
  return hit;
}

Vec2 bounced(const RailLine& rail, Vec2 dir, double restitution) {
  const double n = dot(dir, rail.normal);
  return dir - rail.normal * (n * (1.0 + restitution));
}

const BallState* objectBall(const std::vector<BallState>& balls, int id) {
  return id == kCueBall ? nullptr : findOnTable(balls, id);
}

const BallState* findOnTable(const std::vector<BallState>& balls, int id) {
  for (const BallState& b : balls) {
    if (b.id == id && !b.pocket) return &b;
  }
  return nullptr;
}

}  // namespace nineball::ai
