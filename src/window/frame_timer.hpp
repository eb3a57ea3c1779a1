#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace nineball::window {

/// Frame times kept to report the frame rate: the median over the frames in which balls
/// moved.
class FrameTimer {
 public:
  void add(double seconds) { times_.push_back(seconds); }
  std::size_t count() const { return times_.size(); }
  void clear() { times_.clear(); }

  /// The q-quantile (0.5: the median) of the frame times in seconds; 0 when empty.
  double quantile(double q) const {
    if (times_.empty()) return 0.0;
    std::vector<double> sorted = times_;
    std::sort(sorted.begin(), sorted.end());
    const auto i = static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1) + 0.5);
    return sorted[std::min(i, sorted.size() - 1)];
  }

 private:
  std::vector<double> times_;
};

}  // namespace nineball::window
