// A traced run's state at any instant, in `nineball._core`: state_at (one instant, a dict per
// ball) and state_at_times (an array of instants, arrays out). Both carry each ball's last sample
// at or before the instant on by the closed form of its free motion.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "module_parts.hpp"
#include "nineball/motion.hpp"
#include "nineball/trace.hpp"

namespace nineball::python {
namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The ball's `name` column of a trace (a numpy array or a list), checked to hold `n` rows.
py::sequence traceColumn(const py::dict& ball, const char* name, const std::string& key,
                         std::size_t n) {
  if (!ball.contains(name)) {
    throw py::value_error("result: trace[\"" + key + "\"] has no \"" + name + "\" column");
  }
  const py::object column = ball[name];
  if (!py::isinstance<py::sequence>(column) || py::len(column) != n) {
    throw py::value_error("result: trace[\"" + key + "\"][\"" + name + "\"] is not a column of " +
                          std::to_string(n) + " samples");
  }
  return column.cast<py::sequence>();
}

double cell(const py::sequence& column, std::size_t i) {
  return py::float_(column[i]).cast<double>();
}

// The index of the last sample at or before t (the samples are in time order).
std::size_t lastSampleAtOrBefore(const py::sequence& times, std::size_t n, double t) {
  std::size_t lo = 0;
  std::size_t hi = n;  // cell(times, lo) <= t < cell(times, hi), hi = n standing for +inf
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (cell(times, mid) <= t) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return lo;
}

// The pocket each ball of a result dropped into, by id (as the trace's keys spell it).
std::map<std::string, py::object> pocketsOf(const py::dict& result) {
  std::map<std::string, py::object> pockets;
  if (!result.contains("balls")) return pockets;
  for (py::handle b : result["balls"]) {
    if (!py::isinstance<py::dict>(b)) continue;
    const py::dict ball = b.cast<py::dict>();
    if (ball.contains("id") && ball.contains("pocket")) {
      pockets[py::str(ball["id"]).cast<std::string>()] = ball["pocket"];
    }
  }
  return pockets;
}

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
  if (!ball.contains("w"))
    throw py::value_error("result: trace[\"" + key + "\"] has no \"w\" column");
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

// Every ball of a traced result at time t: its last sample at or before t carried on by the
// closed form of its free motion under the scene's physics. No event lies between the two
// (every event's instant is sampled), so this is the run's own motion, not an interpolation.
py::list stateAt(py::handle result_given, double t, py::handle scene) {
  if (!py::isinstance<py::dict>(result_given)) {
    throw py::type_error("result: expected the dict simulate returned");
  }
  const py::dict result = result_given.cast<py::dict>();
  if (!result.contains("trace") || !py::isinstance<py::dict>(result["trace"])) {
    throw py::value_error(
        "result: has no trace; simulate the scene with \"trace\": {\"events_only\": true} "
        "(exact at any instant) or {\"hz\": ...}");
  }
  if (!std::isfinite(t)) throw py::value_error("t: expected a finite number of seconds");
  const PhysicsParams physics = parse(scene, "scene: ").physics;
  const bool truncated =
      result.contains("trace_truncated") && result["trace_truncated"].cast<bool>();
  const std::map<std::string, py::object> pockets = pocketsOf(result);
  py::list out;
  for (auto item : result["trace"].cast<py::dict>()) {
    const std::string key = py::str(item.first).cast<std::string>();
    const py::dict ball = item.second.cast<py::dict>();
    const std::size_t n = ball.contains("t") ? py::len(ball["t"]) : 0;
    if (n == 0) throw py::value_error("result: trace[\"" + key + "\"] has no samples");
    const py::sequence times = traceColumn(ball, "t", key, n);
    const double first = cell(times, 0);
    const double last = cell(times, n - 1);
    if (t < first && first > 0.0) {
      throw py::value_error("t: " + py::str(py::float_(t)).cast<std::string>() +
                            " s is before the trace's first sample (" +
                            py::str(py::float_(first)).cast<std::string>() +
                            " s; an events-only trace starts at the first event): trace with "
                            "{\"hz\": 1} or more to cover the run from 0");
    }
    if (t < first || t > last) {
      throw py::value_error("t: " + py::str(py::float_(t)).cast<std::string>() +
                            " s is outside the " + (truncated ? "truncated trace" : "run") + " (" +
                            py::str(py::float_(first)).cast<std::string>() + " to " +
                            py::str(py::float_(last)).cast<std::string>() + " s)");
    }
    const std::size_t k = lastSampleAtOrBefore(times, n, t);
    const std::string phase = py::str(traceColumn(ball, "phase", key, n)[k]).cast<std::string>();
    const py::sequence spins = traceColumn(ball, "w", key, n);
    BallState b;
    b.id = std::stoi(key);
    b.pos = {cell(traceColumn(ball, "x", key, n), k), cell(traceColumn(ball, "y", key, n), k)};
    b.vel = {cell(traceColumn(ball, "vx", key, n), k), cell(traceColumn(ball, "vy", key, n), k)};
    const py::sequence w = py::reinterpret_borrow<py::object>(spins[k]).cast<py::sequence>();
    b.w = {cell(w, 0), cell(w, 1), cell(w, 2)};
    // A trace written before balls could leave the cloth has no heights: they are 0.
    if (ball.contains("z") && ball.contains("vz")) {
      b.z = cell(traceColumn(ball, "z", key, n), k);
      b.vz = cell(traceColumn(ball, "vz", key, n), k);
    }
    const bool pocketed = phase == tracePhaseName(TracePhase::Pocketed);
    if (!pocketed) b = freeMotion(b, t - cell(times, k), physics);
    py::dict one;
    one["id"] = b.id;
    one["x"] = b.pos.x;
    one["y"] = b.pos.y;
    one["vx"] = b.vel.x;
    one["vy"] = b.vel.y;
    one["z"] = b.z;
    one["vz"] = b.vz;
    py::list spin;
    spin.append(b.w.x);
    spin.append(b.w.y);
    spin.append(b.w.z);
    one["w"] = spin;
    one["phase"] = pocketed ? phase : tracePhaseName(freePhase(b, physics));
    const auto dropped = pockets.find(key);
    one["pocket"] = pocketed && dropped != pockets.end() ? dropped->second : py::none();
    out.append(one);
  }
  return out;
}

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
    balls.push_back(
        columnsOf(py::str(item.first).cast<std::string>(), item.second.cast<py::dict>()));
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
