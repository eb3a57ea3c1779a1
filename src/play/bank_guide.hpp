#pragma once

#include <optional>
#include <vector>

#include "play/aim_guide.hpp"

namespace nineball {

/// The cue ball's path on from the first cushion its aim guide meets: the guide's direction
/// mirrored in the cushion's normal (a plain reflection, no spin, no cushion nose), traced
/// from where the ball touches the cushion as computeAimGuide traces the aim. Nothing when
/// the guide does not end on a cushion.
std::optional<AimGuide> bankGuide(const TableGeometry& table, double ball_radius,
                                  const std::vector<BallState>& balls, const AimGuide& guide);

}  // namespace nineball
