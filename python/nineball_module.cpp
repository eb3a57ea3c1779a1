// The Python package's compiled core `nineball._core` (python/nineball/ wraps it): a thin skin over
// the same scene parser, checks, engines and result format as `nineball sim`. A scene goes dict ->
// JSON text -> the parser, so that a bad one is refused with the command line's very message; the
// result comes back as the same structure, with traces as numpy arrays when numpy is there.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <functional>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "module_parts.hpp"
#include "nineball/cancel.hpp"
#include "nineball/json.hpp"
#include "nineball/motion.hpp"
#include "nineball/rules.hpp"
#include "nineball/scenes.hpp"
#include "nineball/sim.hpp"
#include "nineball/table.hpp"

namespace py = pybind11;

namespace nineball::python {
namespace {

// JSON has no numpy scalars or arrays: they go as the numbers and lists they hold.
py::object plain(py::handle o) {
  if (py::hasattr(o, "tolist")) return o.attr("tolist")();
  throw py::type_error(
      "a scene holds only dicts, lists, strings, numbers, booleans and None, "
      "found " +
      py::str(py::type::of(o)).cast<std::string>());
}

// A numpy value as the plain Python value it holds; anything else as it is.
py::object plainValue(py::handle o) {
  if (py::hasattr(o, "tolist")) return o.attr("tolist")();
  return py::reinterpret_borrow<py::object>(o);
}

// Deeper than any scene, recording or script is nested (a scene's deepest is 4): a document
// nested deeper (or holding itself) is refused before anything recurses through it.
constexpr int kMaxNesting = 64;

// The first number in `o` that JSON cannot hold (NaN or an infinity), as "balls[0].x"; empty
// when there is none. JSON text would only say where in the text the parser stopped.
std::string nonFiniteAt(py::handle given, const std::string& path, int depth = 0) {
  if (depth > kMaxNesting) {
    throw py::value_error((path.empty() ? std::string("scene") : path) + ": nested deeper than " +
                          std::to_string(kMaxNesting) +
                          " levels (a dict or list that holds itself?)");
  }
  const py::object o = plainValue(given);  // a numpy array is looked into as its list
  if (py::isinstance<py::float_>(o)) {
    return std::isfinite(o.cast<double>()) ? std::string() : path;
  }
  if (py::isinstance<py::dict>(o)) {
    for (auto item : o.cast<py::dict>()) {
      const std::string key = py::str(item.first).cast<std::string>();
      const std::string found =
          nonFiniteAt(item.second, path.empty() ? key : path + "." + key, depth + 1);
      if (!found.empty()) return found;
    }
  } else if (py::isinstance<py::list>(o) || py::isinstance<py::tuple>(o)) {
    std::size_t i = 0;
    for (py::handle v : o) {
      const std::string found = nonFiniteAt(v, path + "[" + std::to_string(i++) + "]", depth + 1);
      if (!found.empty()) return found;
    }
  }
  return {};
}

// A ball id written as a float with no fraction (from a numpy float array: 3.0) as the int it
// is; the command line, reading JSON text, takes integers only.
py::object withIntegerIds(py::handle scene) {
  if (!py::isinstance<py::dict>(scene) || !scene.cast<py::dict>().contains("balls")) {
    return py::reinterpret_borrow<py::object>(scene);
  }
  const py::object balls = scene.cast<py::dict>()["balls"];
  if (!py::isinstance<py::list>(balls) && !py::isinstance<py::tuple>(balls)) {
    return py::reinterpret_borrow<py::object>(scene);
  }
  py::list fixed;
  bool changed = false;
  for (py::handle b : balls) {
    py::object ball = py::reinterpret_borrow<py::object>(b);
    if (py::isinstance<py::dict>(b) && b.cast<py::dict>().contains("id")) {
      py::object id = plainValue(b.cast<py::dict>()["id"]);
      if (py::isinstance<py::float_>(id)) {
        const double d = id.cast<double>();
        if (std::isfinite(d) && d == std::floor(d) && std::abs(d) < 1e15) {
          py::dict copy(b.cast<py::dict>());
          copy["id"] = py::int_(static_cast<long long>(d));
          ball = copy;
          changed = true;
        }
      }
    }
    fixed.append(ball);
  }
  if (!changed) return py::reinterpret_borrow<py::object>(scene);
  py::dict copy(scene.cast<py::dict>());
  copy["balls"] = fixed;
  return copy;
}

// The scene as the command line would read it: a str is the JSON text itself.
std::string sceneText(py::handle given, const std::string& where) {
  if (py::isinstance<py::str>(given)) return given.cast<std::string>();
  const py::object scene = withIntegerIds(given);
  const std::string bad = nonFiniteAt(scene, "");
  if (!bad.empty()) {
    throw py::value_error(where + bad + ": expected a finite number, found NaN or an infinity");
  }
  // Looked up on each call: a static Python object would outlive the interpreter.
  const py::object dumps = py::module_::import("json").attr("dumps");
  return dumps(scene, py::arg("default") = py::cpp_function(plain)).cast<std::string>();
}

py::object numpyOrNothing() {
  try {
    return py::module_::import("numpy");
  } catch (const py::error_already_set&) {
    return py::none();
  }
}

py::object column(const std::vector<double>& v, bool arrays) {
  if (!arrays) return py::cast(v);
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

py::dict traceToPython(const Trace& trace) {
  const py::object numpy = numpyOrNothing();
  const bool arrays = !numpy.is_none();
  py::dict out;
  for (const BallTrace& b : trace.balls) {
    py::dict one;
    one["t"] = column(b.t, arrays);
    one["x"] = column(b.x, arrays);
    one["y"] = column(b.y, arrays);
    one["vx"] = column(b.vx, arrays);
    one["vy"] = column(b.vy, arrays);
    one["z"] = column(b.z, arrays);
    one["vz"] = column(b.vz, arrays);
    py::list phase;
    for (TracePhase p : b.phase) phase.append(tracePhaseName(p));
    if (arrays) {
      py::array_t<double> w({static_cast<py::ssize_t>(b.size()), py::ssize_t{3}});
      auto cells = w.mutable_unchecked<2>();
      for (std::size_t i = 0; i < b.size(); ++i) {
        const auto row = static_cast<py::ssize_t>(i);
        cells(row, 0) = b.w[i].x;
        cells(row, 1) = b.w[i].y;
        cells(row, 2) = b.w[i].z;
      }
      one["w"] = w;
      one["phase"] = numpy.attr("array")(phase);
    } else {
      py::list rows;
      for (const Vec3& v : b.w) {
        py::list row;
        row.append(v.x);
        row.append(v.y);
        row.append(v.z);
        rows.append(row);
      }
      one["w"] = rows;
      one["phase"] = phase;
    }
    out[py::str(std::to_string(b.id))] = one;
  }
  return out;
}

// What of a scene a result needs to go on from where it stopped (continue_from): its table,
// physics and step as given, and the masses of its balls.
py::dict settingOf(py::handle given) {
  const py::object scene = py::isinstance<py::str>(given)
                               ? py::module_::import("json").attr("loads")(given)
                               : py::reinterpret_borrow<py::object>(given);
  py::dict out;
  if (!py::isinstance<py::dict>(scene)) return out;
  const py::dict d = scene.cast<py::dict>();
  for (const char* key : {"table", "physics", "step"}) {
    if (d.contains(key)) out[key] = d[key];
  }
  py::list masses;
  if (d.contains("balls") && py::isinstance<py::list>(d["balls"])) {
    for (py::handle b : d["balls"]) {
      if (py::isinstance<py::dict>(b) && b.cast<py::dict>().contains("mass")) {
        py::dict one;
        one["id"] = b.cast<py::dict>()["id"];
        one["mass"] = b.cast<py::dict>()["mass"];
        masses.append(one);
      }
    }
  }
  out["balls"] = masses;
  return out;
}

// The result document of `nineball sim`, as Python objects (a nineball.Result, which keeps the
// physics the run used for state_at); the trace (which can be large) goes straight from the
// samples, not through JSON text.
py::object resultToPython(SimResult result, const PhysicsParams& physics, py::handle scene) {
  const py::object loads = py::module_::import("json").attr("loads");
  std::optional<Trace> trace = std::move(result.trace);
  result.trace.reset();
  py::object doc = loads(resultJsonText(result));
  if (trace) {
    doc["trace"] = traceToPython(*trace);
    doc["trace_truncated"] = trace->truncated;
    if (trace->truncated) {
      // The command line says so on stderr; a notebook shows a warning.
      if (PyErr_WarnEx(PyExc_RuntimeWarning,
                       "the trace stopped at its sample limit before the run ended "
                       "(trace_truncated); ask for a lower hz or a shorter run",
                       1) != 0) {
        throw py::error_already_set();  // warnings turned into errors
      }
    }
  }
  py::object out = py::module_::import("nineball").attr("Result")(doc, physicsJsonText(physics));
  out.attr("_setting") = settingOf(scene);
  return out;
}

// A result that breaks its promises (a ball off the table, a number not finite) is a defect
// of the engine: raised, never returned.
void checkResult(const Scene& scene, const SimResult& result, const std::string& where) {
  if (const auto fault = resultFault(scene, result)) {
    throw std::runtime_error(where + "internal error: " + *fault);
  }
}

py::object simulateOne(py::handle scene) {
  const Scene s = parse(scene, "");
  SimResult r;
  runInterruptibly([&](const std::atomic<bool>* cancel) {
    const CancelScope scope(cancel);
    r = simulate(s);
  });
  checkResult(s, r, "");
  return resultToPython(std::move(r), s.physics, scene);
}

py::list simulateMany(py::handle scenes, py::handle threads_given, std::size_t first_index) {
  if (py::isinstance<py::dict>(scenes) || py::isinstance<py::str>(scenes) ||
      py::isinstance<py::bytes>(scenes)) {
    throw py::type_error(std::string("scenes: expected a list of scenes, found one ") +
                         (py::isinstance<py::dict>(scenes) ? "dict (use simulate, or [scene])"
                                                           : "string (use simulate, or [scene])"));
  }
  if (!py::isinstance<py::iterable>(scenes)) {
    throw py::type_error("scenes: expected a list of scenes, found " +
                         py::str(py::type::of(scenes).attr("__name__")).cast<std::string>());
  }
  const int threads = threadCount(threads_given);
  std::vector<Scene> parsed;
  std::vector<py::object> given;
  std::size_t i = 0;
  for (py::handle scene : scenes) {
    parsed.push_back(parse(scene, "scenes[" + std::to_string(first_index + i) + "]: "));
    given.push_back(py::reinterpret_borrow<py::object>(scene));
    ++i;
  }
  std::vector<SimResult> results;
  runInterruptibly(
      [&](const std::atomic<bool>* cancel) { results = simulateMany(parsed, threads, cancel); });
  py::list out;
  for (std::size_t k = 0; k < results.size(); ++k) {
    checkResult(parsed[k], results[k], "scenes[" + std::to_string(first_index + k) + "]: ");
    out.append(resultToPython(std::move(results[k]), parsed[k].physics, given[k]));
  }
  return out;
}

// The scene that goes on from where `result` (of `scene`) stopped: the scene's table, physics
// and step, every ball still on the table where and as it moves in the result (with its
// mass from the scene), and the given shot and until (none: roll on to rest).
py::dict continueFrom(py::handle scene_given, py::handle result, py::object shot,
                      py::object until) {
  if (!py::isinstance<py::dict>(result) || !result.cast<py::dict>().contains("balls")) {
    throw py::type_error("result: expected the dict simulate returned");
  }
  const py::object loads = py::module_::import("json").attr("loads");
  const py::dict scene = loads(sceneText(scene_given, "scene: ")).cast<py::dict>();
  py::dict masses;
  if (scene.contains("balls")) {
    for (py::handle b : scene["balls"]) {
      const py::dict ball = b.cast<py::dict>();
      if (ball.contains("mass") && ball.contains("id")) masses[ball["id"]] = ball["mass"];
    }
  }
  py::list balls;
  for (py::handle b : result.cast<py::dict>()["balls"]) {
    const py::dict ball = b.cast<py::dict>();
    if (ball.contains("pocket") && !ball["pocket"].is_none()) continue;
    if (ball.contains("off_table") && ball["off_table"].cast<bool>()) continue;
    py::dict next;
    for (const char* key : {"id", "x", "y", "vx", "vy", "w"}) {
      if (ball.contains(key)) next[key] = plainValue(ball[key]);
    }
    // A ball in the air goes on from its height; one on the cloth is given none (the cloths
    // that keep every ball on it refuse a height).
    for (const char* key : {"z", "vz"}) {
      if (ball.contains(key) && plainValue(ball[key]).cast<double>() != 0.0) {
        next[key] = plainValue(ball[key]);
      }
    }
    if (masses.contains(ball["id"])) next["mass"] = masses[ball["id"]];
    balls.append(next);
  }
  py::dict out;
  for (auto item : scene) {
    const std::string key = py::str(item.first).cast<std::string>();
    if (key != "balls" && key != "shot" && key != "until" && key != "trace") {
      out[item.first] = item.second;
    }
  }
  out["balls"] = balls;
  if (!shot.is_none()) out["shot"] = shot;
  if (!until.is_none()) out["until"] = until;
  return out;
}

// A JSON contract of a headless command run on `doc` (its text in, its JSON text out),
// interruptible, its refusal a ValueError, its answer as Python objects.
py::object runContract(py::handle doc,
                       std::variant<std::string, SceneRefusal> (*contract)(std::string_view)) {
  const std::string text = sceneText(doc, "");
  std::variant<std::string, SceneRefusal> answer;
  runInterruptibly([&](const std::atomic<bool>* cancel) {
    const CancelScope scope(cancel);
    answer = contract(text);
  });
  if (const auto* refused = std::get_if<SceneRefusal>(&answer)) {
    throw py::value_error(refused->message);
  }
  return py::module_::import("json").attr("loads")(std::get<std::string>(answer));
}

// What `nineball match` prints for the script.
py::object matchOf(py::handle script) {
  return runContract(script, &matchJsonText);
}

// The physics preset `name` as a scene's physics object.
py::object presetOf(const std::string& name) {
  const std::optional<std::string> text = presetJsonText(name);
  if (!text) {
    std::string expected;
    const std::vector<std::string> names = PhysicsParams::presetNames();
    for (std::size_t i = 0; i < names.size(); ++i) {
      expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ("\"" + names[i] + "\"");
    }
    throw py::value_error("preset: unknown preset \"" + name + "\" (expected " + expected + ")");
  }
  return py::module_::import("json").attr("loads")(*text);
}

// What `nineball plan` prints for the scene (with "game", "rules", "ball_in_hand", "level").
py::object planOf(py::handle scene) {
  return runContract(scene, &planJsonText);
}

// Recorded shots as JSON text: one dict, a list of them, or the text itself (JSON or JSON
// Lines), numpy arrays written as lists.
std::string recordingsText(py::handle shots) {
  if (py::isinstance<py::str>(shots)) return shots.cast<std::string>();
  const std::string bad = nonFiniteAt(shots, "shots");
  if (!bad.empty())
    throw py::value_error(bad + ": expected a finite number, found NaN or an infinity");
  const py::object dumps = py::module_::import("json").attr("dumps");
  return dumps(shots, py::arg("default") = py::cpp_function(plain)).cast<std::string>();
}

// The text of a contract's answer; its refusal as a ValueError.
const std::string& answerText(const std::variant<std::string, SceneRefusal>& answer) {
  if (const auto* refused = std::get_if<SceneRefusal>(&answer)) {
    throw py::value_error(refused->message);
  }
  return std::get<std::string>(answer);
}

py::object jsonAnswer(const std::variant<std::string, SceneRefusal>& answer) {
  return py::module_::import("json").attr("loads")(answerText(answer));
}

// What `nineball fit` prints for the shots, a dict per shot.
py::list fitOf(py::handle shots, int evals, const std::string& objective, std::uint64_t seed,
               py::handle threads) {
  if (objective != "full" && objective != "early") {
    throw py::value_error("objective: expected \"full\" or \"early\", found \"" + objective + "\"");
  }
  if (evals < kMinFitEvals) {
    throw py::value_error("evals: must be >= " + std::to_string(kMinFitEvals));
  }
  const std::string text = recordingsText(shots);
  FitOptions o;
  o.evals = evals;
  o.objective = objective == "early" ? FitObjective::Early : FitObjective::Full;
  o.seed = seed;
  o.threads = threadCount(threads);
  std::variant<std::string, SceneRefusal> answer;
  runInterruptibly([&](const std::atomic<bool>* cancel) {
    o.cancel = cancel;
    answer = fitJsonText(text, o);
  });
  py::list out;
  const py::object loads = py::module_::import("json").attr("loads");
  std::istringstream lines(answerText(answer));
  for (std::string line; std::getline(lines, line);) out.append(loads(line));
  return out;
}

// What `nineball calibrate` prints for the shots.
py::object calibrateOf(py::handle shots, const std::vector<std::string>& params, double holdout,
                       std::uint64_t seed, int evals, int refit_evals, int candidates,
                       py::handle threads) {
  const std::string text = recordingsText(shots);
  CalibrateRequest r;
  r.params = params;
  r.holdout = holdout;
  r.seed = seed;
  r.evals = evals;
  r.refit_evals = refit_evals;
  r.candidates = candidates;
  r.threads = threadCount(threads);
  std::variant<std::string, SceneRefusal> answer;
  runInterruptibly([&](const std::atomic<bool>* cancel) {
    r.cancel = cancel;
    answer = calibrateJsonText(text, r);
  });
  return jsonAnswer(answer);
}

// A scene recorded as a tracker would.
py::object recordOf(py::handle scene, const std::vector<std::string>& names, double hz,
                    double noise, double strike, std::uint64_t seed) {
  Tracker t;
  t.hz = hz;
  t.noise = noise;
  t.strike = strike;
  t.seed = seed;
  return jsonAnswer(recordingJsonText(sceneText(scene, ""), names, t));
}

// A result (or a scene) as JSON text: numpy arrays and numbers as the lists and numbers they
// hold, so that a result with a trace serialises.
std::string toJson(py::handle doc) {
  const py::object dumps = py::module_::import("json").attr("dumps");
  return dumps(doc, py::arg("default") = py::cpp_function(plain)).cast<std::string>();
}

}  // namespace

// `threads` as given, checked: an int (not a bool) of 0 (one per core) up to the cores there
// are; more would only queue behind each other, and thousands could fail to start.
int threadCount(py::handle threads) {
  if (!py::isinstance<py::int_>(threads) || py::isinstance<py::bool_>(threads)) {
    throw py::type_error("threads: expected an int, found " +
                         py::str(py::type::of(threads).attr("__name__")).cast<std::string>());
  }
  const long long n = threads.cast<long long>();
  const long long cores = std::max(1u, std::thread::hardware_concurrency());
  if (n < 0) throw py::value_error("threads: must be >= 0 (0: one per core)");
  return static_cast<int>(std::min(n, cores));
}

// How often a waiting call looks for Ctrl-C.
constexpr std::chrono::milliseconds kSignalPoll{25};

// Runs `work` on a thread of its own, the GIL released, and looks for a signal (Ctrl-C, a
// notebook's "interrupt kernel") every kSignalPoll meanwhile: on one, the flag handed to
// `work` stops its runs at their next event, and once they have stopped the handler's
// exception (KeyboardInterrupt) is raised, the unfinished results dropped. Without a thread
// to be had it runs where it is, uninterruptible as before.
void runInterruptibly(const std::function<void(const std::atomic<bool>*)>& work) {
  std::atomic<bool> cancel{false};
  std::exception_ptr failure;
  bool done = false;
  bool interrupted = false;
  std::mutex m;
  std::condition_variable finished;
  {
    const py::gil_scoped_release unlocked;
    std::thread worker;
    try {
      worker = std::thread([&] {
        try {
          work(&cancel);
        } catch (...) {
          failure = std::current_exception();
        }
        const std::lock_guard<std::mutex> lock(m);
        done = true;
        finished.notify_all();
      });
    } catch (const std::system_error&) {
      work(nullptr);
      return;
    }
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(m);
        if (finished.wait_for(lock, kSignalPoll, [&] { return done; })) break;
      }
      const py::gil_scoped_acquire locked;
      if (PyErr_CheckSignals() != 0) {
        interrupted = true;
        cancel = true;
        break;
      }
    }
    worker.join();
  }
  if (interrupted) throw py::error_already_set();
  if (failure) std::rethrow_exception(failure);
}

Scene parse(py::handle scene, const std::string& where) {
  const std::string text = sceneText(scene, where);
  // The command line's bound on what it reads, so that both take the same scenes.
  if (text.size() > maxSceneBytes()) {
    throw py::value_error(where + "scene: larger than " + std::to_string(maxSceneBytes() >> 20) +
                          " MiB as JSON, more than any scene needs");
  }
  auto parsed = readScene(text);
  if (const auto* refused = std::get_if<SceneRefusal>(&parsed)) {
    throw py::value_error(where + refused->message);
  }
  return std::get<Scene>(std::move(parsed));
}

}  // namespace nineball::python

PYBIND11_MODULE(_core, m) {
  m.doc() = "The compiled core of the nineball package: see help(nineball).";
  m.attr("__version__") = NINEBALL_VERSION;
  m.attr("PRESETS") = py::tuple(py::cast(nineball::PhysicsParams::presetNames()));
  m.attr("TABLES") = py::tuple(py::cast(nineball::TableDef::names()));
  m.attr("EVENT_TYPES") = nineball::python::eventTypeNames();
  m.def("simulate", &nineball::python::simulateOne, py::arg("scene"),
        "Simulates one scene (a dict or JSON text) and returns the result dict.");
  m.def("continue_from", &nineball::python::continueFrom, py::arg("scene"), py::arg("result"),
        py::arg("shot") = py::none(), py::arg("until") = py::none(),
        "The scene that goes on from where `result` (of `scene`) stopped: the scene's table, "
        "physics and step, every ball still on the table as the result left it (its mass from "
        "the scene), and `shot` and `until` if given (else the balls roll on to rest). Feed it "
        "to simulate.");
  m.def("state_at", &nineball::python::stateAt, py::arg("result"), py::arg("t"), py::arg("scene"),
        "Every ball of a traced result at time t (s): its last sample at or before t carried on "
        "by the closed form of its free motion under the scene's physics.");
  m.def("table_geometry", &nineball::python::tableGeometry, py::arg("scene"),
        "The table of a scene (its table and physics) as the physics builds it: size, pockets, "
        "cushion loop, spots.");
  m.def("rack", &nineball::python::rackOf, py::arg("game"), py::arg("seed"), py::arg("scene"),
        "The standard rack of a game on the scene's table, seeded as the game seeds it.");
  m.def("match", &nineball::python::matchOf, py::arg("script"),
        "What `nineball match` prints for the script: a rack played to its end.");
  m.def("preset", &nineball::python::presetOf, py::arg("name"),
        "A physics preset (\"real\", \"paper\") as a scene's physics object, every parameter "
        "its models read.");
  m.def("plan", &nineball::python::planOf, py::arg("scene"),
        "What `nineball plan` prints for the scene: the shot the computer would play.");
  m.def("to_json", &nineball::python::toJson, py::arg("doc"),
        "A result or scene as JSON text, numpy arrays (a trace's) written as lists.");
  m.def("fit", &nineball::python::fitOf, py::arg("shots"), py::arg("evals"), py::arg("objective"),
        py::arg("seed"), py::arg("threads"),
        "What `nineball fit` prints for the recorded shots: a dict per shot.");
  m.def("calibrate", &nineball::python::calibrateOf, py::arg("shots"), py::arg("params"),
        py::arg("holdout"), py::arg("seed"), py::arg("evals"), py::arg("refit_evals"),
        py::arg("candidates"), py::arg("threads"),
        "What `nineball calibrate` prints for the recorded shots.");
  m.def("record", &nineball::python::recordOf, py::arg("scene"), py::arg("names"), py::arg("hz"),
        py::arg("noise"), py::arg("strike"), py::arg("seed"),
        "The scene recorded as a tracker would: a recorded shot.");
  nineball::python::defineEnv(m);
  m.def("simulate_arrays", &nineball::python::simulateArrays, py::arg("scene"), py::arg("places"),
        py::arg("shots"), py::arg("ids"), py::arg("threads") = 0,
        "Ball places (n x balls x 2) and strokes (n x 5) on the scene's table: the final states, "
        "event counts and event times as arrays.");
  m.def("batch_arrays", &nineball::python::batchArrays, py::arg("scenes"), py::arg("threads") = 0,
        py::arg("first_index") = 0, "Scenes in, simulate_arrays' arrays out.");
  m.def("state_at_times", &nineball::python::stateAtTimes, py::arg("result"), py::arg("times"),
        py::arg("scene"), "A traced run's balls at each instant of an array, as arrays.");
  m.def("simulate_many", &nineball::python::simulateMany, py::arg("scenes"), py::arg("threads") = 0,
        py::arg("first_index") = 0,
        "Checks every scene first (ValueError naming scenes[i] and the field), then simulates "
        "them on `threads` threads (0: one per core; more than the cores are capped to them) "
        "with the GIL released; the results in order. `first_index`: the index of the first "
        "scene in messages (a chunk of a longer batch).");
}
