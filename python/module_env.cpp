// The game environment's tables in `nineball._core` (nineball.env wraps them): N tables of a
// game or the potting task stepped side by side in C++, the GIL released, observations written
// straight into numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "env/vec_tables.hpp"
#include "io/json_reader.hpp"
#include "io/match_json.hpp"
#include "io/parse_error.hpp"
#include "io/standing_json.hpp"
#include "module_parts.hpp"
#include "nineball/games.hpp"

namespace nineball::python {
namespace {

using nlohmann::json;

// A flat action's columns: heading_deg, speed, side, height, elevation_deg, cue_x, cue_y.
constexpr py::ssize_t kActionColumns = 7;
// More tables than any learner steps at once (each holds a match and its engine): a larger n is
// a mistake, refused before the memory goes.
constexpr std::size_t kMaxTables = 10000;

json jsonOf(py::handle o, const std::string& where) {
  const py::object dumps = py::module_::import("json").attr("dumps");
  std::string text;
  try {
    text = dumps(o, py::arg("default") = py::cpp_function([](py::handle v) -> py::object {
                      if (py::hasattr(v, "tolist")) return v.attr("tolist")();
                      throw py::type_error("not a JSON value");
                    }),
                 py::arg("allow_nan") = false)
               .cast<std::string>();
  } catch (const py::error_already_set& e) {
    // NaN or an infinity ("Out of range float values..."), a dict holding itself ("Circular
    // reference detected"), an object JSON has no word for.
    throw py::value_error(where + ": expected a dict of finite numbers, lists and strings (" +
                          std::string(py::str(e.value())) + ")");
  }
  return io::readJson(text);
}

env::Rewards rewardsOf(py::handle given) {
  env::Rewards r;
  if (given.is_none()) return r;
  if (!py::isinstance<py::dict>(given)) throw py::type_error("rewards: expected a dict");
  for (auto item : given.cast<py::dict>()) {
    const std::string key = py::str(item.first).cast<std::string>();
    double* slot = key == "pot"     ? &r.pot
                   : key == "point" ? &r.point
                   : key == "foul"  ? &r.foul
                   : key == "win"   ? &r.win
                   : key == "loss"  ? &r.loss
                                    : nullptr;
    if (!slot) {
      throw py::value_error("rewards." + key +
                            ": unknown reward (expected pot, point, foul, win or loss)");
    }
    const py::handle value = item.second;
    const bool number = (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value) ||
                         py::hasattr(value, "__float__")) &&
                        !py::isinstance<py::bool_>(value) && !py::isinstance<py::str>(value);
    if (!number) throw py::type_error("rewards." + key + ": expected a number");
    const double v = py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
    if (!std::isfinite(v)) throw py::value_error("rewards." + key + ": expected a finite number");
    *slot = v;
  }
  return r;
}

class Tables {
 public:
  Tables(const std::string& name, long long n, const std::optional<std::string>& opponent,
         const std::string& noise, const std::string& engine, std::uint64_t seed,
         py::handle threads, py::handle rewards, int max_turns)
      : tables_(specOf(name, opponent, noise, engine, rewards, max_turns), checkedSize(n), seed,
                threadCount(threads)) {}

  std::size_t size() const { return tables_.size(); }
  std::vector<int> ids() const { return tables_.at(0).ids(); }
  std::pair<double, double> tableSize() const {
    const TableDef& t = tables_.at(0).spec().table;
    return {t.length, t.width};
  }
  static std::vector<std::string> stateNames() {
    return {std::begin(env::kStateNames), std::end(env::kStateNames)};
  }

  py::tuple reset(std::optional<std::uint64_t> seed, py::handle starts) {
    std::vector<std::optional<MatchSetup>> setups(size());
    if (!starts.is_none()) {
      const py::list given(py::reinterpret_borrow<py::object>(starts));
      if (given.size() != size()) {
        throw py::value_error("starts: expected " + std::to_string(size()) + " positions");
      }
      for (std::size_t i = 0; i < size(); ++i) {
        if (!given[i].is_none()) setups[i] = startOf(given[i], "starts[" + std::to_string(i) + "]");
      }
    }
    try {
      const py::gil_scoped_release unlocked;
      tables_.reset(seed, setups);
    } catch (const std::invalid_argument& e) {
      throw py::value_error(e.what());
    }
    return observation();
  }

  py::tuple stepArray(const py::array_t<double, py::array::c_style | py::array::forcecast>& a,
                      bool autoreset) {
    if (a.ndim() != 2 || static_cast<std::size_t>(a.shape(0)) != size() ||
        a.shape(1) != kActionColumns) {
      throw py::value_error("actions: expected an array of shape (" + std::to_string(size()) +
                            ", 7): heading_deg, speed, side, height, elevation_deg, cue_x, cue_y");
    }
    std::vector<env::Action> actions(size());
    const auto rows = a.unchecked<2>();
    for (std::size_t i = 0; i < size(); ++i) actions[i] = rowAction(rows, i);
    return run(actions, autoreset);
  }

  py::tuple stepDicts(const py::list& given, bool autoreset) {
    if (given.size() != size()) {
      throw py::value_error("actions: expected " + std::to_string(size()) + " actions");
    }
    std::vector<env::Action> actions(size());
    for (std::size_t i = 0; i < size(); ++i) {
      const std::string where = "actions[" + std::to_string(i) + "]";
      const env::TableEnv& t = tables_.at(i);
      if (t.over()) continue;  // a table standing still: its action (None will do) is ignored
      try {
        actions[i] = io::parseTurn(jsonOf(given[i], where), where, t.spec().physics.ball_mass,
                                   t.match().rack().game());
      } catch (const io::ParseError& e) {
        throw py::value_error(e.message);
      }
      if (auto problem = t.actionProblem(actions[i]))
        throw py::value_error(where + ": " + *problem);
    }
    return run(actions, autoreset);
  }

  py::list teacher(const std::string& level_name) const {
    const auto level = ai::levelFromName(level_name);
    if (!level) throw py::value_error("level: unknown level \"" + level_name + "\"");
    std::vector<std::string> texts(size());
    {
      const py::gil_scoped_release unlocked;
      for (std::size_t i = 0; i < size(); ++i) {
        const env::TableEnv& t = tables_.at(i);
        texts[i] =
            t.over() ? "null" : io::turnToJson(t.teacher(*level), t.match().rack().game()).dump();
      }
    }
    py::list out;
    const py::object loads = py::module_::import("json").attr("loads");
    for (const std::string& text : texts) out.append(loads(text));
    return out;
  }

  double lastStepSeconds() const { return last_step_seconds_; }

 private:
  static std::size_t checkedSize(long long n) {
    if (n < 1 || n > static_cast<long long>(kMaxTables)) {
      throw py::value_error("n: expected from 1 to " + std::to_string(kMaxTables) +
                            " tables, found " + std::to_string(n));
    }
    return static_cast<std::size_t>(n);
  }

  static env::EnvSpec specOf(const std::string& name, const std::optional<std::string>& opponent,
                             const std::string& noise, const std::string& engine,
                             py::handle rewards, int max_turns) {
    env::EnvSpec spec;
    try {
      spec = env::EnvSpec::named(name, opponent, noise, engine);
    } catch (const std::invalid_argument& e) {
      throw py::value_error(e.what());
    }
    spec.rewards = rewardsOf(rewards);
    if (max_turns < 1) throw py::value_error("max_turns: must be >= 1");
    spec.max_turns = max_turns;
    return spec;
  }

  // A position to start from: "balls" and the standing keys, read as a match script reads them.
  MatchSetup startOf(py::handle given, const std::string& where) const {
    const env::EnvSpec& spec = tables_.at(0).spec();
    if (!spec.game) throw py::value_error(where + ": the pot task starts from a random pot");
    json doc = jsonOf(given, where);
    if (!doc.is_object()) throw py::value_error(where + ": expected a dict");
    for (const auto& item : doc.items()) {
      bool known = item.key() == "balls";
      for (const char* k : io::kStandingKeys) known = known || item.key() == k;
      if (!known) {
        throw py::value_error(where + "." + item.key() +
                              ": unknown field (expected balls, shooter, ball_in_hand, fouls, "
                              "groups, score)");
      }
    }
    doc["game"] = spec.name;
    doc["turns"] = json::array();
    const io::MatchScriptResult parsed = io::parseMatchScript(doc.dump());
    if (const auto* e = std::get_if<io::ParseError>(&parsed)) {
      throw py::value_error(where + "." + e->message);
    }
    return std::get<io::MatchScript>(parsed).setup;
  }

  env::Action rowAction(const py::detail::unchecked_reference<double, 2>& rows,
                        std::size_t i) const {
    const auto r = static_cast<py::ssize_t>(i);
    const std::string where = "actions[" + std::to_string(i) + "]";
    const env::TableEnv& t = tables_.at(i);
    json turn = {{"heading_deg", rows(r, 0)},
                 {"speed", rows(r, 1)},
                 {"tip", {rows(r, 2), rows(r, 3)}},
                 {"elevation_deg", rows(r, 4)}};
    env::Action action;
    try {
      action = io::parseTurn(turn, where, t.spec().physics.ball_mass, t.match().rack().game());
    } catch (const io::ParseError& e) {
      throw py::value_error(e.message);
    }
    if (t.over()) return env::Action{};  // a table standing still: its action is ignored
    const Vec2 cue{rows(r, 5), rows(r, 6)};
    // A flat action's place counts only when the ball is in hand and may go there.
    if (std::isfinite(cue.x) && std::isfinite(cue.y) && t.match().cueInHand() &&
        !t.match().cuePlacementProblem(cue)) {
      action.cue = cue;
    }
    return t.completed(action);
  }

  py::tuple run(const std::vector<env::Action>& actions, bool autoreset) {
    std::vector<env::StepOutcome> outcomes;
    try {
      const py::gil_scoped_release unlocked;
      const auto started = std::chrono::steady_clock::now();
      outcomes = tables_.step(actions, autoreset);
      last_step_seconds_ =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    } catch (const IllegalAction& e) {
      throw py::value_error(e.what());
    }
    const auto n = static_cast<py::ssize_t>(size());
    py::array_t<double> reward(n);
    py::array_t<bool> terminated(n), truncated(n), legal(n);
    py::array_t<long long> potted(n), opponent_turns(n), winner(n);
    py::array_t<double> executed({n, kActionColumns});
    auto ex = executed.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < n; ++i) {
      const env::StepOutcome& o = outcomes[static_cast<std::size_t>(i)];
      reward.mutable_at(i) = o.reward;
      terminated.mutable_at(i) = o.terminated;
      truncated.mutable_at(i) = o.truncated;
      legal.mutable_at(i) = o.legal;
      potted.mutable_at(i) = o.potted;
      opponent_turns.mutable_at(i) = o.opponent_turns;
      winner.mutable_at(i) = !o.winner ? -1 : *o.winner == rules::Player::A ? 0 : 1;
      const bool stroke = !o.idle && o.executed.kind != TurnInput::Kind::Decision;
      const Shot& s = o.executed.shot;
      const double row[kActionColumns] = {stroke ? radToDeg(s.heading_rad) : kNaN,
                                          stroke ? s.speed : kNaN,
                                          stroke ? s.tip.x : kNaN,
                                          stroke ? s.tip.y : kNaN,
                                          stroke ? radToDeg(s.elevation_rad) : kNaN,
                                          stroke && o.executed.cue ? o.executed.cue->x : kNaN,
                                          stroke && o.executed.cue ? o.executed.cue->y : kNaN};
      for (py::ssize_t c = 0; c < kActionColumns; ++c) ex(i, c) = row[c];
    }
    const py::tuple obs = observation();
    return py::make_tuple(obs[0], obs[1], obs[2], reward, terminated, truncated, executed, legal,
                          potted, opponent_turns, winner);
  }

  py::tuple observation() const {
    const auto n = static_cast<py::ssize_t>(size());
    const auto k = static_cast<py::ssize_t>(ids().size());
    py::array_t<double> places({n, k, py::ssize_t{2}});
    py::array_t<std::uint8_t> on_table({n, k});
    py::array_t<double> state({n, py::ssize_t{env::kStateSize}});
    for (py::ssize_t i = 0; i < n; ++i) {
      tables_.at(static_cast<std::size_t>(i))
          .observe(places.mutable_data(i), on_table.mutable_data(i), state.mutable_data(i));
    }
    return py::make_tuple(places, on_table.attr("astype")("bool"), state);
  }

  env::VecTables tables_;
  double last_step_seconds_ = 0.0;
};

}  // namespace

void defineEnv(py::module_& m) {
  m.attr("GAMES") = py::tuple(py::cast(gameNames()));
  m.attr("NOISE_MODELS") = py::tuple(py::cast(ai::cueingNames()));
  py::class_<Tables>(m, "Tables")
      .def(py::init<const std::string&, long long, const std::optional<std::string>&,
                    const std::string&, const std::string&, std::uint64_t, py::handle, py::handle,
                    int>(),
           py::arg("name"), py::arg("n"), py::arg("opponent"), py::arg("noise"), py::arg("engine"),
           py::arg("seed"), py::arg("threads"), py::arg("rewards"), py::arg("max_turns"))
      .def("__len__", &Tables::size)
      .def_property_readonly("ids", &Tables::ids)
      .def_property_readonly("table_size", &Tables::tableSize)
      .def_property_readonly_static("state_names",
                                    [](const py::object&) { return Tables::stateNames(); })
      .def("reset", &Tables::reset, py::arg("seed"), py::arg("starts"))
      .def("step_array", &Tables::stepArray, py::arg("actions"), py::arg("autoreset"))
      .def("step_dicts", &Tables::stepDicts, py::arg("actions"), py::arg("autoreset"))
      .def("teacher", &Tables::teacher, py::arg("level"))
      .def_property_readonly("last_step_seconds", &Tables::lastStepSeconds);
}

}  // namespace nineball::python
