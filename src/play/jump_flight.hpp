#pragma once

#include <vector>

#include "nineball/ball.hpp"
#include "nineball/params.hpp"
#include "nineball/shot.hpp"
#include "play/aim_guide.hpp"

// Where a jumping cue ball flies, alone on the table, from the closed forms of docs/physics.md
// ("Balls in the air"): what the aim guide shows and what the computer plans a jump with.
namespace nineball::play {

/// One flight: from where the ball leaves the cloth to where it comes down, its centre's
/// height a parabola over the straight line between them.
struct Flight {
  Vec2 from;
  Vec2 to;
  double vz = 0.0;  ///< m/s up as it leaves the cloth
  double gravity = 9.81;
  double speed = 0.0;  ///< m/s on the table's plane

  /// The centre's height (m above resting on the cloth) `along` m from `from`.
  double heightAt(double along) const;
  double apex() const { return vz * vz / (2.0 * gravity); }
};

/// The cue ball's flights after `shot` from `cue`: the jump and each bounce that lifts it
/// again (each landing a frictional bounce, bounceOffSlate), until it stays on the cloth; at
/// most `max_flights`. Empty when the stroke leaves it on the cloth, is a miscue, or the cloth
/// lets no ball leave it.
std::vector<Flight> cueBallFlights(const PhysicsParams& p, Vec2 cue, const Shot& shot,
                                   int max_flights = 8);

/// True when no flight brings the ball's centre within 2R + margin of the resting `ball`'s, in
/// space (it passes over it, or lands short of it, or beside it).
bool flightsClear(const std::vector<Flight>& flights, const BallState& ball, double radius,
                  double margin = 0.0);

/// The aim guide of `shot` from `cue` (computeAimGuide) when it may jump: the balls its flights
/// pass over are left out of the trace, and `landings` holds where it comes down before the first
/// thing it meets. A shot that stays on the cloth has computeAimGuide's guide.
AimGuide jumpAimGuide(const TableGeometry& table, const PhysicsParams& p,
                      const std::vector<BallState>& balls, Vec2 cue, const Shot& shot,
                      int cue_id = kCueBall);

}  // namespace nineball::play
