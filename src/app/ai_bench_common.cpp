#include "app/ai_bench_common.hpp"

#include <algorithm>

namespace nineball::app {

ai::Planner benchPlanner(const AiBenchOptions& o, ai::Level level, std::uint64_t seed) {
  if (const auto noise = ai::ExecutionNoise::named(o.noise)) {
    return ai::Planner(level, *noise, seed, o.threads);
  }
  return ai::Planner(level, seed, o.threads);
}

double medianOf(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace nineball::app
