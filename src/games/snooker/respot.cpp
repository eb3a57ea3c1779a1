#include "games/snooker/respot.hpp"

#include "games/snooker/spots.hpp"
#include "rules/snooker_balls.hpp"

namespace nineball::snooker {
namespace {

// The line towards a cushion is walked in steps this small (m) looking for room.
constexpr double kStep = 0.0005;
using rules::snooker::kBlack;
using rules::snooker::kYellow;

bool free(Vec2 p, int ball, const TableGeometry& table, double r,
          const std::vector<BallState>& balls) {
  if (!table.ballFits(p, r)) return false;
  for (const BallState& b : balls) {
    if (b.pocket || b.id == ball) continue;
    if (length(b.pos - p) < 2.0 * r) return false;
  }
  return true;
}

}  // namespace

Vec2 respotPlace(int ball, const TableGeometry& table, double r,
                 const std::vector<BallState>& balls) {
  const Vec2 own = colourSpot(table.def, ball);
  if (free(own, ball, table, r, balls)) return own;
  for (int spot = kBlack; spot >= kYellow; --spot) {
    const Vec2 p = colourSpot(table.def, spot);
    if (free(p, ball, table, r, balls)) return p;
  }
  for (double dir : {1.0, -1.0}) {
    for (Vec2 p = own; table.insideLoop(p); p.x += dir * kStep) {
      if (free(p, ball, table, r, balls)) return p;
    }
  }
  return own;
}

}  // namespace nineball::snooker
