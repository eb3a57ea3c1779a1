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

std::optional<CushionModel> CushionModel::fromName(const std::string& name) {
  if (const auto i = placeNamed(physics::cushionModels(), name)) return CushionModel(*i);
  return std::nullopt;
}

CushionModel CushionModel::named(const std::string& name) {
  if (auto m = fromName(name)) return *m;
  throw std::invalid_argument("no cushion model named \"" + name + "\"");
}

std::vector<std::string> CushionModel::names() {
  return namesOf(physics::cushionModels());
}

bool CushionModel::reads(const std::string& parameter) const {
  return holds(physics::cushionModel(*this).reads, parameter);
}

bool CushionModel::ignores(const std::string& parameter) const {
  return holds(physics::cushionModel(*this).ignores, parameter);
}

const char* CushionModel::name() const {
  return physics::cushionModel(*this).name;
}

}  // namespace nineball
