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

std::optional<EngineKind> EngineKind::fromName(const std::string& name) {
  if (const auto i = placeNamed(physics::engines(), name)) return EngineKind(*i);
  return std::nullopt;
}

EngineKind EngineKind::named(const std::string& name) {
  if (auto e = fromName(name)) return *e;
  throw std::invalid_argument("no engine named \"" + name + "\"");
}

std::vector<std::string> EngineKind::names() {
  return namesOf(physics::engines());
}

const char* EngineKind::name() const {
  return physics::engines()[index_].name;
}

const char* EngineKind::lacks() const {
  return physics::engines()[index_].lacks;
}

bool EngineKind::reads(const std::string& field) const {
  return holds(physics::engines()[index_].reads, field);
}

}  // namespace nineball
