#include "physics/engines/box2d/box2d_settings_check.hpp"

#include <cmath>

namespace nineball::physics {

std::optional<std::string> box2dSettingsProblem(const TableGeometry& table,
                                                const StepParams& step) {
  const Box2DSettings& b = step.box2d;
  if (!std::isfinite(b.scale) || b.scale <= 0.0) {
    return std::string("step.scale: must be a finite number > 0");
  }
  if (b.velocity_iterations < 1) return std::string("step.velocity_iterations: must be >= 1");
  if (b.position_iterations < 0) return std::string("step.position_iterations: must be >= 0");
  // Box2D refuses cushion vertices closer than its linear slop (0.005 units).
  const auto& loop = table.cushion_loop;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    if (length(loop[(i + 1) % loop.size()] - loop[i]) * b.scale < 0.01) {
      return std::string("step.scale: too small for this table's cushion geometry");
    }
  }
  return std::nullopt;
}

}  // namespace nineball::physics
