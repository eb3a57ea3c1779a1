#pragma once

#include <cmath>
#include <optional>

#include "nineball/table.hpp"
#include "nineball/vec2.hpp"
#include "nineball/vec3.hpp"

namespace nineball {

/// Id of the cue ball; object balls carry the numbers their game gives them (any other id is
/// allowed in scenes).
constexpr int kCueBall = 0;

/// A ball as the world outside the physics sees it.
struct BallState {
  int id = 0;
  Vec2 pos;                        ///< m
  Vec2 vel;                        ///< m/s
  std::optional<double> mass;      ///< kg; the physics' ball_mass when empty
  std::optional<PocketId> pocket;  ///< set once the ball has dropped (or left the table)
  Vec3 w;                          ///< rad/s, z up; rolling along +x at speed v has w = (0, v/R, 0)
  double z = 0.0;   ///< m, the height of the centre above where it rests on the cloth
  double vz = 0.0;  ///< m/s, its vertical speed (up positive)
  /// The ball left the table over a rail: `pos` is where it crossed the cushion (`pocket` is
  /// then set too, as for every ball off the table, but names no pocket).
  bool off_table = false;

  /// The `pocket` a ball off the table over a rail carries: every ball gone from the table has
  /// `pocket` set, so that a check for a ball gone counts it too; this one names no pocket.
  static constexpr PocketId kOffTablePocket = PocketId::TopLeft;

  /// Takes the ball off the table: into `into`, or over a rail when nothing.
  void takeOff(std::optional<PocketId> into) {
    pocket = into.value_or(kOffTablePocket);
    off_table = !into;
  }
  /// Puts a ball that was gone back on the table (spotted, placed by hand).
  void backOnTable() {
    pocket.reset();
    off_table = false;
  }

  /// Ball `id` at `pos`, moving at `vel` (at rest by default), no spin.
  static BallState at(int id, Vec2 pos, Vec2 vel = {}) {
    BallState b;
    b.id = id;
    b.pos = pos;
    b.vel = vel;
    return b;
  }
};

/// The distance between two balls' centres in space (their heights counted), m.
inline double centreDistance(const BallState& a, const BallState& b) {
  const Vec2 d = b.pos - a.pos;
  const double dz = b.z - a.z;
  return std::sqrt(d.x * d.x + d.y * d.y + dz * dz);
}

}  // namespace nineball
