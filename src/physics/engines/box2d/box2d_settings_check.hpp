#pragma once

#include <optional>
#include <string>

#include "nineball/params.hpp"
#include "nineball/table.hpp"

namespace nineball::physics {

/// What Box2D would assert on (it aborts: nothing can catch it) in the box2d engine's own
/// settings on this table: a message naming the field, or nothing when they can be run.
std::optional<std::string> box2dSettingsProblem(const TableGeometry& table, const StepParams& step);

}  // namespace nineball::physics
