#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "env/table_env.hpp"

namespace nineball::env {

/// N tables of one environment stepped side by side on up to `threads` threads. Table i's
/// episodes are seeded from (seed, i, the episode's number), so what every table plays does not
/// depend on the threads.
class VecTables {
 public:
  VecTables(const EnvSpec& spec, std::size_t n, std::uint64_t seed, int threads);

  std::size_t size() const { return tables_.size(); }
  TableEnv& at(std::size_t i) { return tables_[i]; }
  const TableEnv& at(std::size_t i) const { return tables_[i]; }

  /// Every table's new episode, from `seed` (table i from seed and i) or, when none, from the
  /// next seed of its own sequence; `starts[i]`, when set, the position table i starts from.
  void reset(std::optional<std::uint64_t> seed,
             const std::vector<std::optional<MatchSetup>>& starts = {});
  /// One turn of the agent on every table, side by side (the actions already checked with
  /// TableEnv::actionProblem). With `autoreset`, a table whose episode ended starts its next
  /// at once (the outcome is the ended episode's); without, a table whose episode is over
  /// stands still, its action ignored (StepOutcome::idle), until reset.
  std::vector<StepOutcome> step(const std::vector<Action>& actions, bool autoreset);

 private:
  void resetTable(std::size_t i, const std::optional<MatchSetup>& start = std::nullopt);

  std::vector<TableEnv> tables_;
  std::vector<std::uint64_t> episodes_;
  std::uint64_t seed_;
  int threads_;
};

}  // namespace nineball::env
