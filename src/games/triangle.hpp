#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/random.hpp"
#include "nineball/table.hpp"

namespace nineball::games {

/// The spots of a triangle with `rows` rows, apex on the foot spot, rows growing away from the
/// head: row r holds r + 1 balls. Spot i of row r is number r(r+1)/2 + i.
std::vector<Vec2> triangleSpots(const TableDef& table, double ball_radius, double gap, int rows);

/// Shuffles `v` in place from the seed's state (Fisher-Yates).
template <std::size_t N>
void shuffle(std::array<int, N>& v, std::uint64_t& state) {
  for (std::size_t i = N - 1; i > 0; --i) {
    const std::size_t j = splitmix64(state) % (i + 1);
    std::swap(v[i], v[j]);
  }
}

/// Puts ball `id` at rest at `p`.
void put(std::vector<BallState>& balls, int id, Vec2 p);

}  // namespace nineball::games
