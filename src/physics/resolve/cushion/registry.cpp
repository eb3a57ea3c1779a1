#include "physics/resolve/cushion/registry.hpp"

#include <stdexcept>

#include "common/named.hpp"
#include "physics/resolve/cushion/mathavan_2010/mathavan_2010.hpp"
#include "physics/resolve/cushion/mathavan_speed/mathavan_speed.hpp"
#include "physics/resolve/cushion/simple/simple.hpp"
#include "physics/resolve/cushion/stronge_compliant/stronge_compliant.hpp"

namespace nineball {
namespace physics {

const std::vector<CushionModelDef>& cushionModels() {
  static const std::vector<CushionModelDef> models{
      simpleCushion(),
      mathavan2010Cushion(),
      strongeCompliantCushion(),
      mathavanSpeedCushion(),
  };
  return models;
}

const CushionModelDef& cushionModel(CushionModel m) {
  return cushionModels()[m.index()];
}

}  // namespace physics

std::size_t CushionModel::registrySize() {
  return physics::cushionModels().size();
}

const char* CushionModel::registryName(std::size_t index) {
  return physics::cushionModels()[index].name;
}

bool CushionModel::reads(const std::string& parameter) const {
  return holds(physics::cushionModel(*this).reads, parameter);
}

bool CushionModel::ignores(const std::string& parameter) const {
  return holds(physics::cushionModel(*this).ignores, parameter);
}

}  // namespace nineball
