#pragma once

#include <cstddef>
#include <vector>

#include "nineball/fit.hpp"
#include "nineball/vec2.hpp"

namespace nineball::fit {

/// The speeds a cue gives a ball (m/s): the search's legal range, and the most a recording's
/// samples may imply (no cue strikes harder than a hard break).
constexpr double kMinSpeed = 0.05;
constexpr double kMaxSpeed = 12.0;
/// A ball has moved once it lies this far from where it stood (m): five times a good tracker's
/// noise (the recording's reading and the fit's warnings count moves alike).
constexpr double kMoved = 0.02;
/// A simulation runs at least this long (s), so that a recording (or a window of it) that ends
/// at the strike still runs.
constexpr double kMinRun = 1e-3;

/// What a recording says before any simulation: which ball was struck, where every ball
/// stood at the strike, and a first guess of the strike from the cue ball's early samples.
struct RecordedShot {
  const Recording* recording = nullptr;
  /// Scene ball i stands for recording->balls[order[i]]; the cue ball first.
  std::vector<std::size_t> order;
  /// Each scene ball's position at the strike: the median of its samples before it moves.
  std::vector<Vec2> rest;
  /// The recording's time of the cue ball's first move, and of its first event (another ball
  /// moving, a turn, a cushion), both from the samples.
  double cue_onset = 0.0;
  double first_event = 0.0;
  /// The cue ball's distance from where it stood at its first sample in motion (m).
  double cue_first_move = 0.0;
  /// The first guess: the strike's time, heading (rad) and speed (m/s).
  double strike = 0.0;
  double heading = 0.0;
  double speed = 1.0;
  /// The strike lies in [earliest, latest].
  double earliest = 0.0;
  double latest = 0.0;
  /// The last recorded instant of any ball.
  double end = 0.0;
  /// The cue ball moves from the recording's first sample (it began after the strike): where
  /// it stood at a strike at time t is then its early line carried back to t.
  bool cue_moving_at_start = false;
  Vec2 line_at, line_velocity;
  double line_time = 0.0;

  /// Where the cue ball stood at a strike at recording time `strike`.
  Vec2 cueAtStrike(double struck) const {
    if (!cue_moving_at_start) return rest[0];
    return line_at + line_velocity * (struck - line_time);
  }

  const RecordedPath& path(std::size_t scene_ball) const {
    return recording->balls[order[scene_ball]];
  }
};

/// Reads a checked recording. `radius`: the balls' (to tell a cushion from a turn).
RecordedShot readRecording(const Recording& r);

/// Moves balls that overlap or sink into a cushion (tracking noise) apart, by no more than the
/// overlap, so that the scene is valid.
void separate(std::vector<Vec2>& rest, const TableDef& table, double radius);

}  // namespace nineball::fit
