// Arrays in, arrays out: sweeps of `nineball._core` that take ball places and strokes as numpy
// arrays and give final states, event counts and event times as arrays, no dict per shot; and a
// traced run's state at an array of instants.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "module_parts.hpp"
#include "nineball/motion.hpp"
#include "nineball/sim.hpp"
#include "nineball/trace.hpp"

namespace nineball::python {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr EventType kEventTypes[] = {EventType::BallBall, EventType::Cushion,  EventType::Pocket,
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
  py::array_t<double> time(n), first_t({n, kTypes});
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

// Every scene built from the base scene, the places and the strokes, checked.
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
    Shot shot = Shot::withSpeed(S(i, 0), S(i, 1));
    shot.tip = {S(i, 2), S(i, 3)};
    shot.elevation_rad = S(i, 4) * 3.14159265358979323846 / 180.0;
    s.shot = shot;
    if (const auto problem = validateScene(s)) {
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

namespace nineball::python {
namespace {

// One ball's trace read once into C++: its samples column by column.
struct BallColumns {
  int id = 0;
  std::vector<double> t, x, y, vx, vy, z, vz, wx, wy, wz;
  std::vector<std::string> phase;
};

std::vector<double> doublesOf(const py::dict& ball, const char* name, const std::string& key,
                              std::size_t n) {
  if (!ball.contains(name)) {
    throw py::value_error("result: trace[\"" + key + "\"] has no \"" + name + "\" column");
  }
  const Doubles a = Doubles::ensure(ball[name]);
  if (!a || a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != n) {
    throw py::value_error("result: trace[\"" + key + "\"][\"" + name + "\"] is not a column of " +
                          std::to_string(n) + " samples");
  }
  return {a.data(), a.data() + n};
}

BallColumns columnsOf(const std::string& key, const py::dict& ball) {
  BallColumns c;
  c.id = std::stoi(key);
  const std::size_t n = ball.contains("t") ? py::len(ball["t"]) : 0;
  if (n == 0) throw py::value_error("result: trace[\"" + key + "\"] has no samples");
  c.t = doublesOf(ball, "t", key, n);
  c.x = doublesOf(ball, "x", key, n);
  c.y = doublesOf(ball, "y", key, n);
  c.vx = doublesOf(ball, "vx", key, n);
  c.vy = doublesOf(ball, "vy", key, n);
  const bool heights = ball.contains("z") && ball.contains("vz");
  c.z = heights ? doublesOf(ball, "z", key, n) : std::vector<double>(n, 0.0);
  c.vz = heights ? doublesOf(ball, "vz", key, n) : std::vector<double>(n, 0.0);
  if (!ball.contains("w")) throw py::value_error("result: trace[\"" + key + "\"] has no \"w\" column");
  const Doubles w = Doubles::ensure(py::object(ball["w"]));
  if (!w || w.ndim() != 2 || static_cast<std::size_t>(w.shape(0)) != n || w.shape(1) != 3) {
    throw py::value_error("result: trace[\"" + key + "\"][\"w\"] is not n x 3 spins");
  }
  const auto W = w.unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<py::ssize_t>(i);
    c.wx.push_back(W(r, 0));
    c.wy.push_back(W(r, 1));
    c.wz.push_back(W(r, 2));
  }
  if (!ball.contains("phase") || py::len(ball["phase"]) != n) {
    throw py::value_error("result: trace[\"" + key + "\"] has no \"phase\" column of " +
                          std::to_string(n) + " samples");
  }
  for (py::handle p : ball["phase"]) c.phase.push_back(py::str(p).cast<std::string>());
  return c;
}

}  // namespace

py::dict stateAtTimes(py::handle result_given, const Doubles& times, py::handle scene) {
  if (!py::isinstance<py::dict>(result_given)) {
    throw py::type_error("result: expected the dict simulate returned");
  }
  const py::dict result = result_given.cast<py::dict>();
  if (!result.contains("trace") || !py::isinstance<py::dict>(result["trace"])) {
    throw py::value_error(
        "result: has no trace; simulate the scene with \"trace\": {\"hz\": 1} or more");
  }
  if (times.ndim() != 1) throw py::value_error("t: expected a number or a 1-d array of seconds");
  const PhysicsParams physics = parse(scene, "scene: ").physics;
  std::vector<BallColumns> balls;
  for (auto item : result["trace"].cast<py::dict>()) {
    balls.push_back(columnsOf(py::str(item.first).cast<std::string>(), item.second.cast<py::dict>()));
  }
  const py::ssize_t n = times.shape(0);
  const auto m = static_cast<py::ssize_t>(balls.size());
  const auto T = times.unchecked<1>();
  for (py::ssize_t k = 0; k < n; ++k) {
    for (const BallColumns& b : balls) {
      if (!(T(k) >= b.t.front() && T(k) <= b.t.back())) {
        throw py::value_error("t[" + std::to_string(k) + "]: " + std::to_string(T(k)) +
                              " s is outside the trace (" + std::to_string(b.t.front()) + " to " +
                              std::to_string(b.t.back()) + " s)");
      }
    }
  }
  py::array_t<double> x({n, m}), y({n, m}), vx({n, m}), vy({n, m}), z({n, m}), vz({n, m});
  py::array_t<double> w({n, m, py::ssize_t{3}});
  py::list phases;
  auto X = x.mutable_unchecked<2>(), Y = y.mutable_unchecked<2>();
  auto VX = vx.mutable_unchecked<2>(), VY = vy.mutable_unchecked<2>();
  auto Z = z.mutable_unchecked<2>(), VZ = vz.mutable_unchecked<2>();
  auto W = w.mutable_unchecked<3>();
  const std::string pocketed = tracePhaseName(TracePhase::Pocketed);
  for (py::ssize_t k = 0; k < n; ++k) {
    py::list row;
    for (py::ssize_t j = 0; j < m; ++j) {
      const BallColumns& c = balls[static_cast<std::size_t>(j)];
      const std::size_t i = static_cast<std::size_t>(
          std::upper_bound(c.t.begin(), c.t.end(), T(k)) - c.t.begin() - 1);
      BallState b;
      b.id = c.id;
      b.pos = {c.x[i], c.y[i]};
      b.vel = {c.vx[i], c.vy[i]};
      b.w = {c.wx[i], c.wy[i], c.wz[i]};
      b.z = c.z[i];
      b.vz = c.vz[i];
      const bool down = c.phase[i] == pocketed;
      if (!down) b = freeMotion(b, T(k) - c.t[i], physics);
      X(k, j) = b.pos.x;
      Y(k, j) = b.pos.y;
      VX(k, j) = b.vel.x;
      VY(k, j) = b.vel.y;
      Z(k, j) = b.z;
      VZ(k, j) = b.vz;
      W(k, j, 0) = b.w.x;
      W(k, j, 1) = b.w.y;
      W(k, j, 2) = b.w.z;
      row.append(down ? pocketed : std::string(tracePhaseName(freePhase(b, physics))));
    }
    phases.append(row);
  }
  std::vector<long long> ids;
  for (const BallColumns& c : balls) ids.push_back(c.id);
  py::dict out;
  out["t"] = py::array_t<double>(n, times.data());
  out["ids"] = py::array_t<long long>(m, ids.data());
  out["x"] = x;
  out["y"] = y;
  out["vx"] = vx;
  out["vy"] = vy;
  out["z"] = z;
  out["vz"] = vz;
  out["w"] = w;
  out["phase"] = py::module_::import("numpy").attr("array")(phases);
  return out;
}

}  // namespace nineball::python
