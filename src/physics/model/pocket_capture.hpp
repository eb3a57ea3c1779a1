#pragma once

#include <vector>

#include "nineball/params.hpp"
#include "nineball/table.hpp"
#include "physics/model/contact_times.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

/// What became of a ball whose centre crossed a pocket's fall edge (the drop circle, the edge
/// of the slate): caught, or thrown back onto the table by the pocket's back and facings.
struct PocketFall {
  bool caught = true;
  /// The walls of the pocket (back and facings) met in the air, each as the ball's velocity
  /// just after it (thrown back or not).
  std::vector<Vec2> wall_contacts;
  /// Thrown back: s after the fall at which the centre is over the fall edge again and the ball
  /// is back on the cloth, and its state then.
  double t_out = 0.0;
  Kinematics out;
  /// m the centre had dropped when it came back to the fall edge (thrown back) or, caught at
  /// the edge, when it met it; 0 for a ball caught in the air.
  double drop = 0.0;
};

/// The fall of a ball of state `k` whose centre is on `pocket`'s fall edge, moving in (the
/// "fall" pocket model, docs/physics.md "Pockets: falling, the back and bouncing out"). Off the
/// slate the ball is a projectile: its horizontal velocity and spin kept, its centre dropping
/// z = g t^2 / 2. Its centre moves in a straight line until, first of:
/// - z reaches R (the centre at the slate's level): it can never climb back; caught;
/// - a wall of the pocket (the cushion loop: the cup behind the hole and the jaw facings) is
///   a radius away: the normal velocity reverses with pocket_restitution, the tangential is
///   kept (a frictionless liner), and the flight goes on;
/// - the centre is over the fall edge again, moving out: the ball meets the slate's edge, a
///   step of height z. It pivots on the edge, keeping its angular momentum about it (a sphere
///   onto a step: a rolling ball keeps v_n (1 - 5 z / (7 R)); the fall's downward speed and
///   the spin count too), and climbs back over when the pivoting ball's kinetic energy,
///   7/10 m u^2, exceeds m g z. It comes back rolling along the normal with the speed left once
///   the climb is paid for, its velocity along the edge kept. Otherwise it falls back: caught.
/// A ball that meets more than kMaxPocketWalls walls is caught. Energy never increases.
PocketFall fallIntoPocket(const Kinematics& k, const Pocket& pocket, const Cushions& cushions,
                          const PhysicsParams& p);

/// The most walls a ball meets in the air before it counts as caught (a rattle that lasts).
constexpr int kMaxPocketWalls = 16;

}  // namespace nineball::physics
