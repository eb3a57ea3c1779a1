#include "physics/resolve/jam/jam_counter.hpp"

#include <algorithm>

namespace nineball::physics {

bool JamCounter::jammed(double t, std::size_t i, std::size_t j) {
  if (t != instant_) {
    std::fill(counts_.begin(), counts_.end(), 0);
    instant_ = t;
  }
  auto count = [&](std::size_t k) {
    if (k >= counts_.size()) counts_.resize(k + 1, 0);
    return ++counts_[k] > kJamContacts;
  };
  const bool jam_i = count(i);
  const bool jam_j = j != kCushion && count(j);
  return jam_i || jam_j;
}

}  // namespace nineball::physics
