#include "play/snookered.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::play {
namespace {

// Balls closer than 2R by this (m) touch: the engines leave resting neighbours a hair apart.
constexpr double kTouching = 1e-5;
// An edge path grazes its ball by this much less than 2R (m), so that the ball on itself is
// met and a ball not on exactly in line with the edge does not count as clear.
constexpr double kGraze = 1e-7;

bool isOn(int id, const std::vector<int>& on) {
  return std::find(on.begin(), on.end(), id) != on.end();
}

// Distance from p to the segment a-b.
double toSegment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return length(p - (a + ab * t));
}

// The cue ball's path from `cue` that ends grazing `target` on the side `side` (+1 / -1) is
// clear of every ball not on.
bool edgeFree(Vec2 cue, const BallState& target, double side, const std::vector<int>& on,
              const std::vector<BallState>& balls, double r) {
  const Vec2 to = target.pos - cue;
  const double d = length(to);
  const double miss = 2.0 * r - kGraze;  // the path passes the target's centre this far off
  const double angle = std::asin(std::min(1.0, miss / d));
  const Vec2 u = rotated(to * (1.0 / d), side * angle);
  const Vec2 contact = cue + u * (d * std::cos(angle));  // the cue ball's centre at the graze
  for (const BallState& b : balls) {
    if (b.pocket || b.id == kCueBall || b.id == target.id || isOn(b.id, on)) continue;
    if (toSegment(b.pos, cue, contact) < 2.0 * r) return false;
  }
  return true;
}

}  // namespace

bool snookered(Vec2 cue, const std::vector<int>& on, const std::vector<BallState>& balls,
               double r) {
  bool any_on = false;
  for (const BallState& b : balls) {
    if (b.pocket || b.id == kCueBall || !isOn(b.id, on)) continue;
    any_on = true;
    if (length(b.pos - cue) <= 2.0 * r + kTouching) return false;
    if (edgeFree(cue, b, 1.0, on, balls, r) && edgeFree(cue, b, -1.0, on, balls, r)) return false;
  }
  return any_on;
}

std::vector<int> touchingBalls(Vec2 cue, const std::vector<BallState>& balls, double r) {
  std::vector<int> ids;
  for (const BallState& b : balls) {
    if (b.pocket || b.id == kCueBall) continue;
    if (length(b.pos - cue) <= 2.0 * r + kTouching) ids.push_back(b.id);
  }
  return ids;
}

}  // namespace nineball::play
