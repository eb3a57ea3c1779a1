#pragma once

#include <optional>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/table.hpp"
#include "nineball/vec2.hpp"

// The geometry a planner reasons with before it simulates anything: ghost balls, pocket
// mouths, clear paths, and a rough chance of potting a ball from a given cue-ball spot.
namespace nineball::ai {

/// A point across the pocket's mouth to send a ball of radius `radius` at: `across` -1 .. 1
/// runs from near jaw a to near jaw b, 0 is the middle.
Vec2 pocketAim(const Pocket& pocket, double across, double radius);

/// True when a ball travelling along `dir` (unit) can drop into the pocket: not too steep to
/// the mouth (a side pocket refuses shallow angles).
bool entersPocket(const Pocket& pocket, Vec2 dir);

/// True when a ball of radius `radius` moving from a to b meets none of `balls` (pocketed
/// ones and the ids `skip_a`, `skip_b` left out): no centre within 2 radius of the segment.
bool pathClear(Vec2 a, Vec2 b, double radius, const std::vector<BallState>& balls, int skip_a,
               int skip_b = -1);

/// A pot by the ghost-ball method: where the cue ball must be at contact and the cut.
struct GhostLine {
  Vec2 target;             ///< where the object ball is sent
  Vec2 ghost;              ///< the cue ball's centre at contact
  Vec2 object_dir;         ///< unit, the object ball's direction
  double heading = 0.0;    ///< rad, the cue ball's direction
  double cut = 0.0;        ///< rad, between the cue ball's path and the object ball's
  double to_ghost = 0.0;   ///< m, cue ball to the ghost
  double to_target = 0.0;  ///< m, object ball to the target
};

/// The ghost line that sends the ball at `object` to `target`, or nothing when the cut is too
/// thin to make (about 80 degrees) or the cue ball sits where the ghost ball would.
std::optional<GhostLine> ghostLine(Vec2 cue, Vec2 object, Vec2 target, double radius);

/// A rough chance, 0..1, of potting along the line for a player whose aim errs by
/// `sigma_rad`: how far the aim may stray at the cue for the object ball to still find the
/// pocket's opening (shrinking with both distances and with the cut), against that error.
double potChance(const GhostLine& line, const Pocket& pocket, double radius, double sigma_rad);

/// The best chance of potting `ball_on` from a cue ball at `cue` over every pocket with clear
/// paths (no cushion check); 0 when the ball is not on the table.
double bestPotChance(const TableGeometry& table, double radius, const std::vector<BallState>& balls,
                     Vec2 cue, int ball_on, double sigma_rad);

/// The share, 0..1, of the balls `ids` still on the table that have a clear straight path into
/// some pocket (the cue ball, which will move, left out); 1 when none is left. A ball in a
/// cluster, or behind another ball from every pocket, has none.
double openShare(const TableGeometry& table, double radius, const std::vector<BallState>& balls,
                 const std::vector<int>& ids);

/// One of the four lines a ball's centre bounces off, `radius` inside a cushion nose: the
/// points x with dot(normal, x) = offset; `normal` points off the table.
struct RailLine {
  Vec2 normal;
  double offset = 0.0;
  double half_span = 0.0;  ///< half the line's length, centred on the table's axis
};
constexpr int kRailCount = 4;

/// Rail 0: +x (foot), 1: -x (head), 2: +y (top), 3: -y (bottom).
RailLine railLine(int rail, const TableDef& table, double radius);

/// Where to aim so that a ball bouncing off the rail reaches `p`: its mirror image, pushed
/// `1 / restitution` times as deep because the cushion returns only that part of the normal
/// speed.
Vec2 mirrorAcross(const RailLine& rail, Vec2 p, double restitution);

/// Where the straight path from `a` to the mirrored point `b` crosses the rail line, or
/// nothing when it does not cross within the rail's span.
std::optional<Vec2> railCrossing(const RailLine& rail, Vec2 a, Vec2 b);

/// A direction after bouncing off the rail: the normal part reversed and scaled by e.
Vec2 bounced(const RailLine& rail, Vec2 dir, double restitution);

/// The ball with that id still on the table, or nothing.
const BallState* findOnTable(const std::vector<BallState>& balls, int id);
/// The same for an object ball: nothing for the cue ball's id (a rack with no ball on).
const BallState* objectBall(const std::vector<BallState>& balls, int id);

}  // namespace nineball::ai
