#include "nineball/state_hash.hpp"

#include <cstring>

namespace nineball {

void BitHash::add(double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  hash_ = (hash_ ^ bits) * 1099511628211ULL;
}

void BitHash::add(std::int64_t v) {
  hash_ = (hash_ ^ static_cast<std::uint64_t>(v)) * 1099511628211ULL;
}

std::uint64_t stateHash(const std::vector<BallState>& balls) {
  BitHash h;
  for (const BallState& b : balls) {
    h.add(std::int64_t{b.id});
    for (double v : {b.pos.x, b.pos.y, b.vel.x, b.vel.y, b.w.x, b.w.y, b.w.z}) h.add(v);
    h.add(b.mass.value_or(-1.0));
    h.add(b.pocket ? static_cast<std::int64_t>(*b.pocket) : std::int64_t{-1});
  }
  return h.value();
}

}  // namespace nineball
