#include "physics/engines/registry.hpp"

#include <stdexcept>

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
  const auto& all = physics::engines();
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (name == all[i].name) return EngineKind(i);
  }
  return std::nullopt;
}

EngineKind EngineKind::named(const std::string& name) {
  if (auto e = fromName(name)) return *e;
  throw std::invalid_argument("no engine named \"" + name + "\"");
}

std::vector<std::string> EngineKind::names() {
  std::vector<std::string> out;
  for (const auto& e : physics::engines()) out.emplace_back(e.name);
  return out;
}

const char* EngineKind::name() const {
  return physics::engines()[index_].name;
}

const char* EngineKind::lacks() const {
  return physics::engines()[index_].lacks;
}

bool EngineKind::reads(const std::string& field) const {
  for (const std::string& r : physics::engines()[index_].reads) {
    if (r == field) return true;
  }
  return false;
}

}  // namespace nineball
