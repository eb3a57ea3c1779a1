#include "physics/engines/registry.hpp"

#include <stdexcept>

#include "common/named.hpp"
#include "physics/engines/box2d/world.hpp"
#include "physics/engines/reference/reference_engine.hpp"

namespace nineball {
namespace physics {

const std::vector<EngineDef>& engines() {
  static const std::vector<EngineDef> all{
      box2dEngine(),
      reference::referenceEngine(),
  };
  return all;
}

}  // namespace physics

std::unique_ptr<Engine> makeEngine(const TableDef& table, const PhysicsParams& physics,
                                   const StepParams& step) {
  return physics::engines()[step.engine.index()].make(table, physics, step);
}

std::size_t EngineKind::registrySize() {
  return physics::engines().size();
}

const char* EngineKind::registryName(std::size_t index) {
  return physics::engines()[index].name;
}

const char* EngineKind::lacks() const {
  return physics::engines()[index()].lacks;
}

bool EngineKind::reads(const std::string& field) const {
  return holds(physics::engines()[index()].reads, field);
}

}  // namespace nineball
