#pragma once

#include <cmath>
#include <cstdint>

#include "nineball/vec2.hpp"

// Seeded randomness that is the same on every platform and library (the standard library's
// distributions are not): racks, stress layouts, benchmark positions, the computer's cueing.
namespace nineball {

/// splitmix64: the next number of the sequence held in `state`.
inline std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// Uniform in [lo, hi).
inline double uniform(std::uint64_t& state, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(splitmix64(state) >> 11) * 0x1.0p-53);
}

/// Uniform in (0, 1): never 0, so that its logarithm is finite.
inline double uniformOpen(std::uint64_t& state) {
  return (static_cast<double>(splitmix64(state) >> 11) + 0.5) * 0x1.0p-53;
}

/// Standard normal by Box-Muller.
inline double gaussian(std::uint64_t& state) {
  const double u1 = uniformOpen(state);
  const double u2 = uniformOpen(state);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

}  // namespace nineball
