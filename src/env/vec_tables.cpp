#include "env/vec_tables.hpp"

#include "common/parallel_map.hpp"
#include "nineball/random.hpp"

namespace nineball::env {

VecTables::VecTables(const EnvSpec& spec, std::size_t n, std::uint64_t seed, int threads)
    : episodes_(n, 0), seed_(seed), threads_(threadsFor(threads)) {
  tables_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) tables_.emplace_back(spec);
  reset(seed);
}

void VecTables::resetTable(std::size_t i, const std::optional<MatchSetup>& start) {
  // A seed of its own for each table and episode: splitmix64 over (seed, table, episode).
  std::uint64_t state = seed_ ^ (0x9E3779B97F4A7C15ull * (i + 1));
  state += 0xBF58476D1CE4E5B9ull * ++episodes_[i];
  tables_[i].reset(splitmix64(state), start);
}

void VecTables::reset(std::optional<std::uint64_t> seed,
                      const std::vector<std::optional<MatchSetup>>& starts) {
  if (seed) {
    seed_ = *seed;
    std::fill(episodes_.begin(), episodes_.end(), 0);
  }
  parallelFor(tables_.size(), threads_,
              [&](std::size_t i) { resetTable(i, i < starts.size() ? starts[i] : std::nullopt); });
}

std::vector<StepOutcome> VecTables::step(const std::vector<Action>& actions, bool autoreset) {
  std::vector<StepOutcome> out(tables_.size());
  parallelFor(tables_.size(), threads_, [&](std::size_t i) {
    if (tables_[i].over()) {
      out[i].idle = true;
      out[i].terminated = true;
      return;
    }
    out[i] = tables_[i].step(actions[i]);
    if (autoreset && (out[i].terminated || out[i].truncated)) resetTable(i);
  });
  return out;
}

}  // namespace nineball::env
