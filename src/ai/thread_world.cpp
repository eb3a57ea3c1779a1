#include "ai/thread_world.hpp"

#include <atomic>
#include <memory>

namespace nineball::ai {

std::uint64_t newWorldOwner() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}

Engine& worldForThisThread(std::uint64_t owner, const TableDef& table, const PhysicsParams& physics,
                           const StepParams& step) {
  struct Kept {
    std::uint64_t owner = 0;
    std::unique_ptr<Engine> engine;
  };
  thread_local Kept kept;
  if (kept.owner == owner && kept.engine) {
    kept.engine->reset();
  } else {
    kept.engine = makeEngine(table, physics, step);
    kept.owner = owner;
  }
  return *kept.engine;
}

}  // namespace nineball::ai
