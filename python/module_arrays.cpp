// Arrays in, arrays out: sweeps of `nineball._core` that take ball places and strokes as numpy
// arrays and give final states, event counts and event times as arrays, no dict per shot; and a
// traced run's state at an array of instants.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "common/limits.hpp"
#include "module_parts.hpp"
#include "nineball/sim.hpp"
#include "nineball/table.hpp"

namespace nineball::python {
namespace {

constexpr EventType kEventTypes[] = {EventType::BallBall,  EventType::Cushion, EventType::Pocket,
                                     EventType::AllAtRest, EventType::Miscue,  EventType::Airborne,
                                     EventType::Land,      EventType::OffTable};
constexpr py::ssize_t kTypes = sizeof(kEventTypes) / sizeof(kEventTypes[0]);
// A stroke row's columns: heading_deg, speed, side, height, elevation_deg.
constexpr py::ssize_t kShotColumns = 5;

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

py::ssize_t typeColumn(EventType t) {
  return static_cast<py::ssize_t>(std::find(std::begin(kEventTypes), std::end(kEventTypes), t) -
                                  std::begin(kEventTypes));
}

// The results as arrays, a row per result, a column per id of `ids`.
py::dict pack(const std::vector<SimResult>& results, const std::vector<int>& ids) {
  const auto n = static_cast<py::ssize_t>(results.size());
  const auto m = static_cast<py::ssize_t>(ids.size());
  py::array_t<double> x({n, m}), y({n, m}), vx({n, m}), vy({n, m}), pocket_t({n, m});
  py::array_t<double> w({n, m, py::ssize_t{3}});
  py::array_t<bool> pocketed({n, m}), partial(n);
  py::array_t<double> time(n), wall_ms(n), first_t({n, kTypes});
  py::array_t<long long> events({n, kTypes});
  auto X = x.mutable_unchecked<2>(), Y = y.mutable_unchecked<2>();
  auto VX = vx.mutable_unchecked<2>(), VY = vy.mutable_unchecked<2>();
  auto PT = pocket_t.mutable_unchecked<2>(), FT = first_t.mutable_unchecked<2>();
  auto W = w.mutable_unchecked<3>();
  auto P = pocketed.mutable_unchecked<2>();
  auto E = events.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const SimResult& r = results[static_cast<std::size_t>(i)];
    for (py::ssize_t j = 0; j < m; ++j) {
      X(i, j) = Y(i, j) = VX(i, j) = VY(i, j) = PT(i, j) = kNaN;
      W(i, j, 0) = W(i, j, 1) = W(i, j, 2) = kNaN;
      P(i, j) = false;
    }
    for (const BallState& b : r.balls) {
      const auto at = std::find(ids.begin(), ids.end(), b.id);
      if (at == ids.end()) continue;
      const auto j = static_cast<py::ssize_t>(at - ids.begin());
      X(i, j) = b.pos.x;
      Y(i, j) = b.pos.y;
      VX(i, j) = b.vel.x;
      VY(i, j) = b.vel.y;
      W(i, j, 0) = b.w.x;
      W(i, j, 1) = b.w.y;
      W(i, j, 2) = b.w.z;
      P(i, j) = b.pocket.has_value();
    }
    for (py::ssize_t c = 0; c < kTypes; ++c) {
      E(i, c) = 0;
      FT(i, c) = kNaN;
    }
    for (const Event& e : r.events) {
      const py::ssize_t c = typeColumn(e.type);
      if (E(i, c)++ == 0) FT(i, c) = e.t;
      if (e.type == EventType::Pocket || e.type == EventType::OffTable) {
        const auto at = std::find(ids.begin(), ids.end(), e.a);
        if (at != ids.end()) PT(i, at - ids.begin()) = e.t;
      }
    }
    time.mutable_at(i) = r.time;
    wall_ms.mutable_at(i) = r.wall_ms;
    partial.mutable_at(i) = r.partial();
  }
  py::dict out;
  out["ids"] = py::array_t<long long>(m, std::vector<long long>(ids.begin(), ids.end()).data());
  out["x"] = x;
  out["y"] = y;
  out["vx"] = vx;
  out["vy"] = vy;
  out["w"] = w;
  out["pocketed"] = pocketed;
  out["pocket_time"] = pocket_t;
  out["time"] = time;
  out["wall_ms"] = wall_ms;
  out["partial"] = partial;
  out["events"] = events;
  out["event_types"] = eventTypeNames();
  out["first_event_time"] = first_t;
  return out;
}

std::vector<SimResult> runAll(const std::vector<Scene>& scenes, int threads) {
  std::vector<SimResult> results;
  runInterruptibly(
      [&](const std::atomic<bool>* cancel) { results = simulateMany(scenes, threads, cancel); });
  return results;
}

// Why a stroke row cannot be struck, or nothing: the bounds a scene's "shot" has.
std::optional<std::string> strokeProblem(double heading_deg, double speed, double side,
                                         double height, double elevation_deg) {
  if (!std::isfinite(heading_deg)) return "heading_deg: expected a finite number";
  if (!(speed >= 0.0 && speed <= limits::kMaxSpeed)) {
    return "speed: must be >= 0 and <= " + std::to_string(limits::kMaxSpeed) + " m/s";
  }
  if (!(side * side + height * height <= 1.0)) {
    return "tip: must lie on the ball: side^2 + height^2 <= 1";
  }
  if (!(elevation_deg >= 0.0 && elevation_deg <= 89.0)) {
    return "elevation_deg: must be >= 0 and <= 89";
  }
  return std::nullopt;
}

// Every scene built from the base scene, the places and the strokes, checked (the table
// built once for all of them).
std::vector<Scene> scenesOf(const Scene& base, const Doubles& places, const Doubles& shots,
                            const std::vector<int>& ids) {
  const auto m = static_cast<py::ssize_t>(ids.size());
  if (places.ndim() != 3 || places.shape(1) != m || places.shape(2) != 2) {
    throw py::value_error("places: expected an array of shape (n, " + std::to_string(m) +
                          ", 2): x, y of each ball of ids (NaN: not on the table)");
  }
  const py::ssize_t n = places.shape(0);
  if (shots.ndim() != 2 || shots.shape(0) != n || shots.shape(1) != kShotColumns) {
    throw py::value_error("shots: expected an array of shape (" + std::to_string(n) +
                          ", 5): heading_deg, speed, side, height, elevation_deg");
  }
  const TableGeometry table = buildTable(base.table, base.physics.ball_radius);
  const auto P = places.unchecked<3>();
  const auto S = shots.unchecked<2>();
  std::vector<Scene> scenes(static_cast<std::size_t>(n), base);
  for (py::ssize_t i = 0; i < n; ++i) {
    Scene& s = scenes[static_cast<std::size_t>(i)];
    s.balls.clear();
    for (py::ssize_t j = 0; j < m; ++j) {
      if (std::isnan(P(i, j, 0)) && std::isnan(P(i, j, 1))) continue;
      BallState b;
      b.id = ids[static_cast<std::size_t>(j)];
      b.pos = {P(i, j, 0), P(i, j, 1)};
      s.balls.push_back(b);
    }
    if (const auto problem = strokeProblem(S(i, 0), S(i, 1), S(i, 2), S(i, 3), S(i, 4))) {
      throw py::value_error("row " + std::to_string(i) + ": " + *problem);
    }
    Shot shot = Shot::withSpeed(S(i, 0), S(i, 1));
    shot.tip = {S(i, 2), S(i, 3)};
    shot.elevation_rad = degToRad(S(i, 4));
    s.shot = shot;
    if (const auto problem = validateBalls(s, table)) {
      throw py::value_error("row " + std::to_string(i) + ": " + *problem);
    }
  }
  return scenes;
}

}  // namespace

py::list eventTypeNames() {
  py::list names;
  for (EventType t : kEventTypes) names.append(eventTypeName(t));
  return names;
}

py::dict simulateArrays(py::handle base_scene, const Doubles& places, const Doubles& shots,
                        const std::vector<int>& ids, py::handle threads) {
  const Scene base = parse(base_scene, "scene: ");
  if (std::find(ids.begin(), ids.end(), kCueBall) == ids.end()) {
    throw py::value_error("ids: the strokes strike the cue ball, id 0: it must be among them");
  }
  const std::vector<Scene> scenes = scenesOf(base, places, shots, ids);
  return pack(runAll(scenes, threadCount(threads)), ids);
}

py::dict batchArrays(py::handle scenes_given, py::handle threads, std::size_t first_index) {
  std::vector<Scene> scenes;
  std::vector<int> ids;
  std::size_t i = 0;
  for (py::handle scene : scenes_given) {
    scenes.push_back(parse(scene, "scenes[" + std::to_string(first_index + i++) + "]: "));
    for (const BallState& b : scenes.back().balls) ids.push_back(b.id);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return pack(runAll(scenes, threadCount(threads)), ids);
}

}  // namespace nineball::python
