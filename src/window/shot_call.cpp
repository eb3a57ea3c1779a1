#include "window/shot_call.hpp"

#include <algorithm>
#include <limits>

namespace nineball::window {

std::optional<PocketId> pocketNear(const TableGeometry& table, Vec2 pos, double reach) {
  std::optional<PocketId> best;
  double best_d = reach;
  for (const Pocket& p : table.pockets) {
    const double d = length(p.drop_centre - pos);
    if (d <= best_d) {
      best = p.id;
      best_d = d;
    }
  }
  return best;
}

PocketId pocketAlong(const TableGeometry& table, Vec2 from, Vec2 dir) {
  PocketId nearest = table.pockets.empty() ? PocketId::TopLeft : table.pockets[0].id;
  double nearest_d = std::numeric_limits<double>::max();
  std::optional<PocketId> ahead;
  double ahead_d = std::numeric_limits<double>::max();
  for (const Pocket& p : table.pockets) {
    const Vec2 to = p.drop_centre - from;
    const double d = length(to);
    if (d < nearest_d) {
      nearest = p.id;
      nearest_d = d;
    }
    const double along = dot(to, dir);
    if (along <= 0.0) continue;
    const double off = length(to - dir * along);
    if (off < ahead_d) {
      ahead = p.id;
      ahead_d = off;
    }
  }
  return ahead.value_or(nearest);
}

std::optional<rules::Call> obviousCall(const TableGeometry& table,
                                       const std::vector<BallState>& balls, const AimGuide& guide,
                                       int ball_on, const std::vector<int>& callable) {
  const bool aimed = guide.target == AimTarget::Ball &&
                     std::find(callable.begin(), callable.end(), guide.ball) != callable.end();
  const int ball = aimed ? guide.ball : ball_on;
  for (const BallState& b : balls) {
    if (b.id != ball || b.pocket) continue;
    const Vec2 dir = aimed ? guide.object_dir : Vec2{};
    return rules::Call{ball, pocketAlong(table, b.pos, dir)};
  }
  return std::nullopt;
}

}  // namespace nineball::window
