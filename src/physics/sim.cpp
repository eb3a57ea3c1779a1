#include "nineball/sim.hpp"

#include <chrono>
#include <cmath>
#include <set>
#include <string>

#include "nineball/world.hpp"

namespace nineball {
namespace {

// Balls given exactly touching must not be refused for the rounding of their coordinates.
constexpr double kOverlapTolerance = 1e-7;

std::string ballField(std::size_t i) { return "balls[" + std::to_string(i) + "]"; }

}  // namespace

std::optional<std::string> validateScene(const Scene& scene) {
  const double r = scene.physics.ball_radius;
  const TableGeometry table = buildTable(scene.table, r);
  std::set<int> ids;
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const BallState& b = scene.balls[i];
    if (!ids.insert(b.id).second) {
      return ballField(i) + ".id: duplicate id " + std::to_string(b.id);
    }
    if (b.pocket) continue;
    if (!table.ballFits(b.pos, r)) {
      return ballField(i) + ": ball " + std::to_string(b.id) + " at (" + std::to_string(b.pos.x) +
             ", " + std::to_string(b.pos.y) + ") is off the table or overlaps a cushion";
    }
    for (std::size_t j = 0; j < i; ++j) {
      const BallState& o = scene.balls[j];
      if (o.pocket) continue;
      if (length(b.pos - o.pos) < 2.0 * r - kOverlapTolerance) {
        return ballField(i) + ": ball " + std::to_string(b.id) + " overlaps ball " +
               std::to_string(o.id);
      }
    }
  }
  if (scene.shot) {
    bool cue_on_table = false;
    for (const BallState& b : scene.balls) cue_on_table |= b.id == kCueBall && !b.pocket;
    if (!cue_on_table) return std::string("shot: the scene has no cue ball (id 0) to strike");
  }
  return std::nullopt;
}

SimResult simulate(const Scene& scene) {
  World world(scene.table, scene.physics, scene.step);
  for (const BallState& b : scene.balls) world.addBall(b);
  if (scene.shot) world.strike(kCueBall, *scene.shot);

  SimResult result;
  const bool started_at_rest = world.atRest();
  const auto start = std::chrono::steady_clock::now();
  if (scene.until) {
    world.runFor(*scene.until);
  } else {
    world.runUntilRest();
  }
  const auto stop = std::chrono::steady_clock::now();
  result.wall_ms = std::chrono::duration<double, std::milli>(stop - start).count();
  result.steps = world.steps();
  // A run that came to rest early has the same state at the requested time.
  result.time = scene.until && world.atRest() ? *scene.until : world.time();
  result.balls = world.balls();
  result.events = world.events();
  if (started_at_rest) {
    Event rest;
    rest.type = EventType::AllAtRest;
    rest.t = 0.0;
    result.events.push_back(rest);
  }
  return result;
}

}  // namespace nineball
