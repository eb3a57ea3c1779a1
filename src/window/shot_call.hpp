#pragma once

#include <optional>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/rules.hpp"
#include "nineball/table.hpp"
#include "play/aim_guide.hpp"

namespace nineball::window {

/// The pocket a click at `pos` (m) picks: the one whose drop circle's centre is nearest, when
/// it is within `reach` of it. Nothing otherwise.
std::optional<PocketId> pocketNear(const TableGeometry& table, Vec2 pos, double reach);

/// The pocket nearest the path of a ball at `from` going along unit `dir`: the least distance
/// from the line ahead; the nearest pocket to `from` when `dir` is zero or points at none.
PocketId pocketAlong(const TableGeometry& table, Vec2 from, Vec2 dir);

/// "Call the obvious shot": the aim guide's object ball when it is one of `callable`, else
/// `ball_on`, into the pocket nearest the path the guide gives it (or nearest the ball).
/// Nothing when the ball is not on the table.
std::optional<rules::Call> obviousCall(const TableGeometry& table,
                                       const std::vector<BallState>& balls, const AimGuide& guide,
                                       int ball_on, const std::vector<int>& callable);

}  // namespace nineball::window
