#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/event.hpp"
#include "nineball/params.hpp"
#include "nineball/sim.hpp"
#include "nineball/table.hpp"
#include "nineball/vec2.hpp"
#include "physics/engines/box2d/world.hpp"

namespace nineball::physics_test {

/// The targets of the accuracy issue. Every physics test compares against one of these.
/// Velocities just after a ball-ball collision, relative to the formula's value.
constexpr double kCollisionSpeedTolerance = 0.005;
/// Direction of the object ball against the line of centres, degrees, over the cut sweep.
constexpr double kDirectionToleranceDeg = 0.1;
/// Stopping distance (and time) of the cloth model against its closed form.
constexpr double kStoppingTolerance = 0.005;
/// Velocity just after a cushion, relative to the formula's value.
constexpr double kCushionTolerance = 0.01;

/// A playing surface far longer than any straight run in these tests (60 m x 2 m), so that
/// only the cushion a test aims at is ever met.
inline TableDef longTable() {
  TableDef t;
  t.length = 60.0;
  t.width = 2.0;
  return t;
}

/// The real preset with the paper's cloth (constant deceleration mu g, no spin), frictionless
/// balls and simple cushion: the model the paper's closed forms describe.
inline PhysicsParams constantDeceleration(PhysicsParams p = PhysicsParams::real()) {
  p.cloth = ClothModel::Friction;
  p.ball_ball = BallBallModel::named("frictionless");
  p.cushion = CushionModel::named("simple");
  return p;
}

/// The real preset with the cloth switched off, for comparisons that friction would blur.
inline PhysicsParams frictionless(PhysicsParams p = PhysicsParams::real()) {
  p = constantDeceleration(p);
  p.rolling_friction = 0.0;
  return p;
}

inline BallState makeBall(int id, Vec2 pos, Vec2 vel = {},
                          std::optional<double> mass = std::nullopt) {
  BallState b;
  b.id = id;
  b.pos = pos;
  b.vel = vel;
  b.mass = mass;
  return b;
}

/// A world holding `balls`, after checking them as a scene would be checked (on the table,
/// no overlap), so that a test never starts from an impossible layout.
inline std::unique_ptr<World> makeWorld(const TableDef& table, const PhysicsParams& physics,
                                        const StepParams& step,
                                        const std::vector<BallState>& balls) {
  Scene scene;
  scene.table = table;
  scene.physics = physics;
  scene.step = step;
  scene.balls = balls;
  const auto problem = validateScene(scene);
  EXPECT_FALSE(problem.has_value()) << *problem;
  auto world = std::make_unique<World>(table, physics, step);
  for (const BallState& b : balls) world->addBall(b);
  return world;
}

inline bool involves(const Event& e, int ball) {
  return ball < 0 || e.a == ball || e.b == ball;
}

/// The first event of `type` (involving `ball`, when given) in the list.
inline std::optional<Event> firstEvent(const std::vector<Event>& events, EventType type,
                                       int ball = -1) {
  for (const Event& e : events) {
    if (e.type == type && involves(e, ball)) return e;
  }
  return std::nullopt;
}

inline int countEvents(const std::vector<Event>& events, EventType type, int ball = -1) {
  return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const Event& e) {
    return e.type == type && involves(e, ball);
  }));
}

/// Steps until an event of `type` (involving `ball`, when given) happens, at most
/// `max_seconds` of simulated time; returns that event.
inline std::optional<Event> runUntilEvent(World& world, EventType type, double max_seconds,
                                          int ball = -1) {
  const long limit = world.steps() + std::lround(max_seconds * world.stepParams().hz);
  while (world.steps() < limit) {
    const std::size_t seen = world.events().size();
    world.step();
    const auto& events = world.events();
    for (std::size_t i = seen; i < events.size(); ++i) {
      if (events[i].type == type && involves(events[i], ball)) return events[i];
    }
  }
  return std::nullopt;
}

inline BallState stateOf(const World& world, int id) {
  for (const BallState& b : world.balls()) {
    if (b.id == id) return b;
  }
  ADD_FAILURE() << "no ball " << id;
  return {};
}

/// |got - want| relative to |want|; relative to `scale` (the speed that sets the size of the
/// problem, e.g. the approach speed) when the formula's value is zero, where a relative
/// error has no meaning.
inline double relativeError(double got, double want, double scale) {
  const double ref = std::abs(want) > 1e-9 * scale ? std::abs(want) : scale;
  return std::abs(got - want) / ref;
}

/// The same for vectors: length of the difference relative to the formula's length.
inline double vectorError(Vec2 got, Vec2 want, double scale) {
  const double ref = length(want) > 1e-9 * scale ? length(want) : scale;
  return length(got - want) / ref;
}

/// Unsigned angle between two vectors, degrees.
inline double angleBetweenDeg(Vec2 a, Vec2 b) {
  return radToDeg(std::abs(std::atan2(cross(a, b), dot(a, b))));
}

inline std::string formatNumber(double v) {
  std::ostringstream s;
  s << std::setprecision(3) << std::scientific << v;
  return s.str();
}

/// Keeps the worst of a family of measured errors, fails the test for each one over the
/// tolerance, and prints the worst at the end (also as a test property in the XML output) so
/// that the README's table can be filled from a test run.
class WorstError {
 public:
  WorstError(std::string name, double tolerance, std::string unit = "relative")
      : name_(std::move(name)), unit_(std::move(unit)), tolerance_(tolerance) {}
  WorstError(const WorstError&) = delete;
  WorstError& operator=(const WorstError&) = delete;
  ~WorstError() {
    if (!seen_) ADD_FAILURE() << name_ << ": nothing was measured";
    std::cout << "[ measured ] " << name_ << ": worst " << formatNumber(worst_) << " " << unit_
              << " (tolerance " << formatNumber(tolerance_) << ") at " << where_ << std::endl;
    ::testing::Test::RecordProperty(name_, formatNumber(worst_));
  }

  void check(double error, const std::string& where) {
    EXPECT_LE(error, tolerance_) << name_ << " at " << where;
    if (!seen_ || !(error <= worst_)) {  // also keeps a NaN, which must show
      seen_ = true;
      worst_ = error;
      where_ = where;
    }
  }

 private:
  std::string name_;
  std::string unit_;
  double tolerance_;
  bool seen_ = false;
  double worst_ = 0.0;
  std::string where_ = "nothing measured";
};

}  // namespace nineball::physics_test
