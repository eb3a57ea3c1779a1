#pragma once

#include <algorithm>
#include <vector>

namespace nineball::rules {

inline bool contains(const std::vector<int>& v, int x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

inline void erase(std::vector<int>& v, int x) {
  v.erase(std::remove(v.begin(), v.end(), x), v.end());
}

/// The balls of `shot_pocketed` that were on the table: a ball dropping twice, or one the
/// rules already took off, counts once.
inline std::vector<int> newlyPocketed(const std::vector<int>& on_table,
                                      const std::vector<int>& shot_pocketed) {
  std::vector<int> down;
  for (int b : shot_pocketed) {
    if (contains(on_table, b)) down.push_back(b);
  }
  return down;
}

}  // namespace nineball::rules
