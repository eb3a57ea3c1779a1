#pragma once

#include <optional>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/event.hpp"
#include "nineball/params.hpp"
#include "nineball/shot.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// One headless run: a table, its physics, balls, an optional shot of the cue ball.
struct Scene {
  TableDef table;
  PhysicsParams physics;
  StepParams step;
  std::vector<BallState> balls;
  std::optional<Shot> shot;
  std::optional<double> until;  ///< seconds; empty means "until rest"
};

struct SimResult {
  double time = 0.0;     ///< simulated seconds reached
  long steps = 0;        ///< fixed steps computed
  double wall_ms = 0.0;  ///< wall time of the stepping alone
  std::vector<BallState> balls;
  std::vector<Event> events;
};

/// Runs a scene that has already been checked (see validateScene).
SimResult simulate(const Scene& scene);

/// Empty when the scene can be simulated, else a message naming the field and the reason
/// (balls overlapping, off the table, duplicate ids, shot without a cue ball, ...).
std::optional<std::string> validateScene(const Scene& scene);

}  // namespace nineball
