#include "play/bank_guide.hpp"

#include <cmath>

namespace nineball {

std::optional<AimGuide> bankGuide(const TableGeometry& table, double ball_radius,
                                  const std::vector<BallState>& balls, const AimGuide& guide) {
  if (guide.target != AimTarget::Cushion || length(guide.end - guide.start) <= 0.0) {
    return std::nullopt;
  }
  const Vec2 d = normalized(guide.end - guide.start);
  const Vec2 n = guide.cushion_normal;
  const Vec2 out = d - n * (2.0 * dot(d, n));
  return computeAimGuide(table, ball_radius, balls, guide.end, std::atan2(out.y, out.x));
}

}  // namespace nineball
