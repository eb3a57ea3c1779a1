#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "nineball/params.hpp"
#include "nineball/table.hpp"
#include "physics/motion.hpp"

namespace nineball::physics {

/// Two balls meeting with centres along a -> b: the paper's oblique collision (normal part by
/// the 1-D restitution law, tangential part kept). When they part slower than a ball can
/// bounce, spin that would press them together again is stopped: else they would meet in an
/// endless run of ever smaller bounces. Positions and the rest of the spin are kept.
void collideBalls(Kinematics& a, Kinematics& b, double mass_a, double mass_b,
                  const PhysicsParams& p);

/// A ball of a jam (see JamCounter): its state, mass and the cushion faces it touches
/// (normals into the table).
struct JamBall {
  std::size_t index = 0;  ///< the engine's own number for the ball
  Kinematics k;
  double mass = 0.0;
  std::vector<Vec2> faces;
};

/// A contact met in a jam, with every ball that touches it, directly or through others.
struct Jam {
  std::vector<JamBall> balls;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  ///< touching, as positions in balls
};

/// The balls touching ball i or j, and those touching them, and so on, from the centres of
/// every ball (`on_table` false for those gone): the indices, and the touching pairs.
std::pair<std::vector<std::size_t>, std::vector<std::pair<std::size_t, std::size_t>>> jamAround(
    const std::vector<Vec2>& centres, const std::vector<bool>& on_table, std::size_t i,
    std::size_t j, double r);

/// Resolves a jam as one contact: no bounce, every touching pair stopped from closing and
/// every ball from entering its faces, all together. Projected Gauss-Seidel over the jam
/// until nothing closes: a light ball pinned in a wedge, or squeezed between heavy ones,
/// stops them here in one contact instead of thousands. Every stop is inelastic and the
/// projections never lengthen a velocity: no energy is gained.
void settleJam(Jam& jam, const PhysicsParams& p);

/// setApart for every pair of a jam, swept a few times: setting one pair apart may press one
/// of them into a third.
void setJamApart(Jam& jam, const TableGeometry& table, double r);

/// Balls the cloth presses together (a perfectly inelastic pair, the one behind with more
/// topspin) are met again each time they overlap by the touch tolerance, and set back to
/// touching here: each moved half the overlap along the normal, except one that the move
/// would sink into a cushion. Micrometres of position, no velocity: no energy.
void setApart(Kinematics& a, Kinematics& b, const TableGeometry& table, double r);

}  // namespace nineball::physics
