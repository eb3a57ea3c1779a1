#pragma once

#include <optional>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/table.hpp"
#include "nineball/vec2.hpp"

namespace nineball {

/// What the cue ball's straight path meets first.
enum class AimTarget {
  Ball,     ///< an object ball: the guide shows the ghost ball and both directions after
  Cushion,  ///< a cushion (or a jaw) before any ball
  Pocket,   ///< the cue ball itself would drop
};

/// The aim guide of a shot, from the table's geometry alone: the cue ball's path to the first
/// thing it touches and, for a ball, where the two balls go after a plain (stun) hit.
struct AimGuide {
  AimTarget target = AimTarget::Cushion;
  Vec2 start;       ///< the cue ball's centre now
  Vec2 end;         ///< the cue ball's centre where the path ends (the ghost ball for a ball)
  int ball = -1;    ///< id of the object ball hit (target Ball)
  Vec2 object_dir;  ///< unit: the object ball's direction, along the line of centres (Ball)
  /// The cue ball's direction after the contact, along the tangent line (Ball); zero for a
  /// full-ball hit, where a stun shot stops dead.
  Vec2 cue_dir;
  /// Where the object ball's centre, going along object_dir, first meets a cushion, a ball or
  /// a pocket (Ball).
  Vec2 object_end;
  /// The same for the cue ball along cue_dir (Ball, when cue_dir is not zero).
  Vec2 cue_end;
  Vec2 cushion_normal;             ///< unit, pointing into the table (Cushion)
  std::optional<PocketId> pocket;  ///< the pocket the cue ball drops into (Pocket)
  /// Where a jumping cue ball comes down before it meets `end`'s target, in order (empty: it
  /// stays on the cloth). Set by jumpAimGuide (play/jump_flight.hpp).
  std::vector<Vec2> landings;
};

/// Traces the cue ball from `cue` along `heading_rad`: against every other ball still on the
/// table (a circle of radius 2R round its centre), the cushion loop offset by R (rails, jaws
/// and pocket cups) and the pockets' drop circles, and returns the first thing met.
AimGuide computeAimGuide(const TableGeometry& table, double ball_radius,
                         const std::vector<BallState>& balls, Vec2 cue, double heading_rad,
                         int cue_id = kCueBall);

}  // namespace nineball
