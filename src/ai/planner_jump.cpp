#include "ai/planner_jump.hpp"

#include <cmath>

#include "play/jump_flight.hpp"

namespace nineball::ai {
namespace {

// A steeper cue jumps sooner and lands shorter (a blocker close to the cue ball needs one), a
// lower one flies further: the planner tries four, each at the softest speed that works.
constexpr double kJumpElevationsDeg[] = {25.0, 35.0, 45.0, 55.0};
constexpr double kJumpSpeeds[] = {2.5, 3.0, 3.5, 4.0, 4.5, 5.0, 5.5, 6.0, 7.0, 8.0};
// How far apart in space (m) the flying ball's centre must stay from a blocker's beyond 2R:
// room for the level's errors.
constexpr double kJumpClearance = 0.006;

}  // namespace

std::vector<const BallState*> ballsInTheWay(const std::vector<BallState>& balls, Vec2 cue,
                                            double heading, double reach, double radius, int skip) {
  const Vec2 dir = fromAngle(heading);
  std::vector<const BallState*> out;
  for (const BallState& b : balls) {
    if (b.pocket || b.id == kCueBall || b.id == skip) continue;
    const Vec2 to = b.pos - cue;
    const double along = dot(to, dir);
    if (along > 0.0 && along < reach && std::abs(cross(dir, to)) < 2.0 * radius) {
      out.push_back(&b);
    }
  }
  return out;
}

std::vector<JumpStroke> jumpStrokes(const PhysicsParams& p, Vec2 cue, double heading,
                                    const std::vector<const BallState*>& blockers, double land_by) {
  std::vector<JumpStroke> out;
  if (blockers.empty()) return out;
  for (double degrees : kJumpElevationsDeg) {
    for (double speed : kJumpSpeeds) {
      Shot shot;
      shot.heading_rad = heading;
      shot.speed = speed;
      shot.elevation_rad = degToRad(degrees);
      const std::vector<play::Flight> flights = play::cueBallFlights(p, cue, shot);
      if (flights.empty()) continue;
      const double lands_at = length(flights.front().to - cue);
      if (lands_at > land_by) break;  // faster only flies further
      bool all = true;
      for (const BallState* b : blockers) {
        all = all && lands_at > length(b->pos - cue) &&
              play::flightsClear(flights, *b, p.ball_radius, kJumpClearance);
      }
      if (!all) continue;
      out.push_back({shot.elevation_rad, speed, lands_at});
      break;
    }
  }
  return out;
}

}  // namespace nineball::ai
