#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "nineball/params.hpp"
#include "nineball/table.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

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

}  // namespace nineball::physics
