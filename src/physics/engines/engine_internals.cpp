#include "physics/engines/engine_internals.hpp"

#include <stdexcept>

namespace nineball::physics {

EngineInternals& internals(Engine& engine) {
  auto* in = dynamic_cast<EngineInternals*>(&engine);
  if (!in) throw std::logic_error("an engine not made by makeEngine has no arcs to trace");
  return *in;
}

const EngineInternals& internals(const Engine& engine) {
  return internals(const_cast<Engine&>(engine));
}

}  // namespace nineball::physics
