#pragma once

#include <cstdint>
#include <vector>

#include "nineball/ball.hpp"

namespace nineball {

/// FNV-1a over the bits of doubles and integers: a fingerprint that changes with any bit.
class BitHash {
 public:
  void add(double v);
  void add(std::int64_t v);
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 1469598103934665603ULL;
};

/// A fingerprint of every ball's full state (id, position, velocity, spin, mass, pocket), bit
/// for bit: two ways of playing the same turns agree exactly when their hashes do.
std::uint64_t stateHash(const std::vector<BallState>& balls);

}  // namespace nineball
