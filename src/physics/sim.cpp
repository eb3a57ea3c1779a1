#include "nineball/sim.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <string>
#include <thread>

#include "common/limits.hpp"
#include "common/parallel_map.hpp"
#include "nineball/cancel.hpp"
#include "nineball/engine.hpp"
#include "physics/engines/engine_internals.hpp"
#include "physics/engines/registry.hpp"
#include "physics/model/arc_log.hpp"
#include "physics/resolve/cushion/registry.hpp"

namespace nineball {
namespace {

// Balls given exactly touching must not be refused for the rounding of their coordinates.
constexpr double kOverlapTolerance = 1e-7;

std::string ballField(std::size_t i) {
  return "balls[" + std::to_string(i) + "]";
}

bool finite(double v) {
  return std::isfinite(v);
}
bool finite(Vec2 v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}

// What Box2D would assert on (it aborts; nothing can catch it) or what cannot be simulated.
std::optional<std::string> checkSettings(const Scene& scene) {
  const PhysicsParams& p = scene.physics;
  const StepParams& st = scene.step;
  const std::pair<const char*, double> positive[] = {
      {"physics.ball_mass", p.ball_mass}, {"physics.ball_radius", p.ball_radius},
      {"physics.gravity", p.gravity},     {"step.hz", st.hz},
      {"step.max_time", st.max_time},     {"table.length", scene.table.length},
      {"table.width", scene.table.width}};
  for (const auto& [name, v] : positive) {
    if (!finite(v) || v <= 0.0) return std::string(name) + ": must be a finite number > 0";
  }
  const std::pair<const char*, double> non_negative[] = {
      {"physics.rolling_friction", p.rolling_friction},
      {"physics.linear_damping", p.linear_damping},
      {"physics.rest_speed", p.rest_speed}};
  for (const auto& [name, v] : non_negative) {
    // Box2D keeps damping as a float: it must stay finite there too.
    if (!finite(v) || v < 0.0 || v > 1e30) return std::string(name) + ": must be >= 0 and finite";
  }
  if (const auto check = physics::cushionModel(p.cushion).check) {
    if (auto problem = check(p)) return problem;
  }
  if (auto problem = checkTable(scene.table, p.ball_radius)) return problem;
  if (const auto check = physics::engines()[st.engine.index()].check) {
    if (auto problem = check(buildTable(scene.table, p.ball_radius), st)) return problem;
  }
  if (scene.shot) {
    if (!finite(scene.shot->speed) || scene.shot->speed < 0.0) {
      return std::string("shot.speed: must be a finite number >= 0");
    }
    if (!finite(scene.shot->heading_rad)) return std::string("shot.heading_deg: must be finite");
    if (!finite(scene.shot->tip)) return std::string("shot.tip: must be finite");
  }
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const BallState& b = scene.balls[i];
    if (!finite(b.pos) || !finite(b.vel))
      return ballField(i) + ": position and velocity must be finite";
    if (b.mass && (!finite(*b.mass) || *b.mass <= 0.0)) return ballField(i) + ".mass: must be > 0";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> validateScene(const Scene& scene) {
  if (auto problem = checkSettings(scene)) return problem;
  return validateBalls(scene, buildTable(scene.table, scene.physics.ball_radius));
}

std::optional<std::string> validateBalls(const Scene& scene, const TableGeometry& table) {
  const double r = scene.physics.ball_radius;
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
      // In space: a ball in the air may lie over another.
      if (centreDistance(b, o) < 2.0 * r - kOverlapTolerance) {
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

const char* simEndName(SimEnd end) {
  switch (end) {
    case SimEnd::Rest:
      return "rest";
    case SimEnd::Until:
      return "until";
    case SimEnd::MaxTime:
      return "max_time";
    case SimEnd::Budget:
      return "budget";
  }
  return "?";
}

SimEnd simEnd(bool until, bool exhausted, bool at_rest) {
  if (exhausted) return SimEnd::Budget;
  if (until) return SimEnd::Until;
  return at_rest ? SimEnd::Rest : SimEnd::MaxTime;
}

namespace {

// JSON cannot hold NaN or infinity (nlohmann would print null), so such a result is a bug.
bool allFinite(const SimResult& r) {
  bool ok = std::isfinite(r.time) && std::isfinite(r.wall_ms);
  for (const BallState& b : r.balls) ok = ok && finite(b.pos) && finite(b.vel);
  for (const Event& e : r.events) ok = ok && std::isfinite(e.t) && finite(e.va) && finite(e.vb);
  if (!r.trace) return ok;
  for (const BallTrace& b : r.trace->balls) {
    for (std::size_t i = 0; i < b.size() && ok; ++i) {
      ok = std::isfinite(b.t[i]) && finite(Vec2{b.x[i], b.y[i]}) &&
           finite(Vec2{b.vx[i], b.vy[i]}) && std::isfinite(b.w[i].x) && std::isfinite(b.w[i].y) &&
           std::isfinite(b.w[i].z);
    }
  }
  return ok;
}

}  // namespace

std::optional<std::string> resultFault(const Scene& scene, const SimResult& result) {
  if (!allFinite(result)) return std::string("the simulation produced a non-finite number");
  const TableGeometry table = buildTable(scene.table, scene.physics.ball_radius);
  for (const BallState& b : result.balls) {
    if (b.pocket || table.insideLoop(b.pos)) continue;
    return "ball " + std::to_string(b.id) + " ended off the table, at (" + std::to_string(b.pos.x) +
           ", " + std::to_string(b.pos.y) + ") m";
  }
  return std::nullopt;
}

std::size_t maxSceneBytes() {
  return limits::kMaxInputBytes;
}

SimResult simulate(const Scene& scene) {
  const std::unique_ptr<Engine> engine = makeEngine(scene.table, scene.physics, scene.step);
  Engine& world = *engine;
  if (scene.trace) physics::internals(world).logArcs();
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
  result.time = world.time();
  result.balls = world.balls();
  result.events = world.events();
  result.end = simEnd(scene.until.has_value(), world.exhausted(), world.atRest());
  result.budget = world.budgetSpent();
  if (started_at_rest) {
    Event rest;
    rest.type = EventType::AllAtRest;
    rest.t = 0.0;
    result.events.push_back(rest);
  }
  if (scene.trace) {
    result.trace = physics::sampleTrace(*physics::internals(world).arcLog(), result.events,
                                        result.time, *scene.trace, scene.physics);
  }
  return result;
}

std::vector<SimResult> simulateMany(const std::vector<Scene>& scenes, int threads,
                                    const std::atomic<bool>* cancel) {
  std::vector<SimResult> results(scenes.size());
  parallelFor(scenes.size(), threadsFor(threads), [&](std::size_t k) {
    const CancelScope scope(cancel);
    if (!cancelRequested()) results[k] = simulate(scenes[k]);
  });
  return results;
}

}  // namespace nineball
