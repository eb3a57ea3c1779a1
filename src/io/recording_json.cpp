#include "io/recording_json.hpp"

#include <functional>
#include <optional>

#include "io/json_fields.hpp"
#include "io/json_reader.hpp"
#include "io/scene_parts.hpp"

namespace nineball::io {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

std::vector<double> numbers(const json& v, const std::string& path) {
  if (!v.is_array()) refuse(path, "expected an array of numbers, found " + describe(v));
  if (v.size() > limits::kMaxRecordedSamples) {
    refuse(path, "more than " + std::to_string(limits::kMaxRecordedSamples) + " samples");
  }
  std::vector<double> out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(number(v[i], element(path, i)));
  return out;
}

RecordedPath pathFromJson(const std::string& name, const json& v) {
  const std::string path = member("balls", name);
  expectObject(v, path);
  allowOnly(v, path, {"t", "x", "y"});
  RecordedPath p;
  p.name = name;
  p.t = numbers(required(v, path, "t"), member(path, "t"));
  p.x = numbers(required(v, path, "x"), member(path, "x"));
  p.y = numbers(required(v, path, "y"), member(path, "y"));
  return p;
}

std::string idOf(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_integer()) return v.dump();
  refuse("id", "expected a string or an integer, found " + describe(v));
}

// The id a shot gives, whatever else is wrong with it: a refusal's line carries it back.
ordered_json idGiven(const json& shot) {
  if (!shot.is_object()) return nullptr;
  const json* id = optional(shot, "id");
  if (!id || !(id->is_string() || id->is_number_integer())) return nullptr;
  return ordered_json::parse(id->dump());
}

// The id as the recording gave it: an integer's digits as a JSON integer again.
ordered_json idToJson(const Recording& r) {
  if (r.integer_id) {
    ordered_json n = ordered_json::parse(r.id, nullptr, false);
    if (n.is_number_integer()) return n;
  }
  return r.id;
}

ordered_json tableToJson(const TableDef& t) {
  for (const std::string& name : TableDef::names()) {
    const TableDef n = *TableDef::named(name);
    if (n.length == t.length && n.width == t.width && n.pockets == t.pockets &&
        (!t.pockets ||
         (n.corner_pocket == t.corner_pocket && n.side_pocket == t.side_pocket &&
          n.corner_jaw_deg == t.corner_jaw_deg && n.side_jaw_deg == t.side_jaw_deg &&
          n.corner_jaw_radius == t.corner_jaw_radius && n.side_jaw_radius == t.side_jaw_radius))) {
      return name;
    }
  }
  ordered_json j{{"length", t.length}, {"width", t.width}, {"pockets", t.pockets}};
  if (t.pockets) {
    j["corner_pocket"] = t.corner_pocket;
    j["side_pocket"] = t.side_pocket;
    j["corner_jaw_deg"] = t.corner_jaw_deg;
    j["side_jaw_deg"] = t.side_jaw_deg;
    // Sharp jaws (a pool table's) are written as before: only a rounded jaw adds its radius.
    if (t.corner_jaw_radius > 0.0) j["corner_jaw_radius"] = t.corner_jaw_radius;
    if (t.side_jaw_radius > 0.0) j["side_jaw_radius"] = t.side_jaw_radius;
  }
  return j;
}

// A parsed document, freed without needing memory (dismantle).
class Document {
 public:
  explicit Document(json v) : v_(std::move(v)) {}
  ~Document() { dismantle(v_); }
  Document(const Document&) = delete;
  Document& operator=(const Document&) = delete;

  const json& operator*() const { return v_; }

 private:
  json v_;
};

ShotInput shotFrom(const json& v, std::string where) {
  ShotInput in;
  in.where = std::move(where);
  in.id = idGiven(v);
  try {
    in.recording = recordingFromJson(v);
  } catch (const ParseError& e) {
    in.refusal = e.message;
  }
  return in;
}

std::variant<std::vector<ShotInput>, ParseError> shotsOf(const json& doc) {
  if (doc.is_object()) return std::vector<ShotInput>{shotFrom(doc, "")};
  if (!doc.is_array()) {
    return ParseError{"expected a recorded shot, an array of them or JSON Lines, found " +
                      describe(doc)};
  }
  if (doc.empty()) return ParseError{"expected at least one recorded shot"};
  std::vector<ShotInput> shots;
  for (std::size_t i = 0; i < doc.size(); ++i) {
    shots.push_back(shotFrom(doc[i], "shot " + std::to_string(i + 1)));
  }
  return shots;
}

// Calls `each(number, line)` for every line that holds something, numbered from 1, until it
// returns false.
void forEachLine(std::string_view text, const std::function<bool(int, std::string_view)>& each) {
  std::size_t start = 0;
  for (int number = 1; start < text.size(); ++number) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    if (!each(number, line)) return;
  }
}

std::vector<ShotInput> linesOf(std::string_view text) {
  std::vector<ShotInput> shots;
  forEachLine(text, [&](int number, std::string_view line) {
    std::string where = "line " + std::to_string(number);
    try {
      const Document doc(readJson(line));
      shots.push_back(shotFrom(*doc, where));
    } catch (const ParseError& e) {
      ShotInput unreadable;
      unreadable.where = std::move(where);
      unreadable.refusal = e.message;
      shots.push_back(std::move(unreadable));
    }
    return true;
  });
  return shots;
}

// The first line that holds something, when it is a whole JSON object by itself: the text is
// JSON Lines (a document spread over lines, pretty-printed, starts with a line that is not).
bool firstLineIsAnObject(std::string_view text) {
  bool object = false;
  forEachLine(text, [&](int, std::string_view line) {
    try {
      object = readJson(line).is_object();
    } catch (const ParseError&) {
    }
    return false;
  });
  return object;
}

}  // namespace

Recording recordingFromJson(const json& v) {
  expectObject(v, "");
  allowOnly(v, "", {"id", "table", "physics", "balls", "cue_ball"});
  Recording r;
  if (const json* id = optional(v, "id")) {
    r.id = idOf(*id);
    r.integer_id = id->is_number_integer();
  }
  if (const json* t = optional(v, "table")) r.table = parseTable(*t);
  if (const json* p = optional(v, "physics")) r.physics = parsePhysics(*p);
  const json& balls = required(v, "", "balls");
  expectObject(balls, "balls");
  if (balls.empty()) refuse("balls", "no ball recorded");
  if (balls.size() > limits::kMaxBalls) {
    refuse("balls", "more than " + std::to_string(limits::kMaxBalls) + " balls");
  }
  for (const auto& item : balls.items()) r.balls.push_back(pathFromJson(item.key(), item.value()));
  if (const json* c = optional(v, "cue_ball")) r.cue_ball = text(*c, "cue_ball");
  if (auto fault = recordingFault(r)) throw ParseError{*fault};
  return r;
}

std::string ShotInput::namedRefusal() const {
  return where.empty() ? refusal : where + ": " + refusal;
}

std::variant<std::vector<ShotInput>, ParseError> readRecordings(std::string_view text) {
  std::optional<Document> doc;
  try {
    doc.emplace(readJson(text));
  } catch (const ParseError& e) {
    // One document that does not parse whole, unless it is one shot a line.
    if (!firstLineIsAnObject(text)) return e;
    return linesOf(text);
  }
  return shotsOf(**doc);
}

std::variant<std::vector<Recording>, ParseError> parseRecordings(std::string_view text) {
  auto read = readRecordings(text);
  if (auto* refused = std::get_if<ParseError>(&read)) return *refused;
  std::vector<Recording> shots;
  for (ShotInput& in : std::get<std::vector<ShotInput>>(read)) {
    if (!in.recording) return ParseError{in.namedRefusal()};
    shots.push_back(std::move(*in.recording));
  }
  return shots;
}

ordered_json recordingToJson(const Recording& r) {
  ordered_json j;
  j["id"] = idToJson(r);
  j["table"] = tableToJson(r.table);
  j["physics"] = physicsToJson(r.physics);
  ordered_json balls = ordered_json::object();
  for (const RecordedPath& b : r.balls) balls[b.name] = {{"t", b.t}, {"x", b.x}, {"y", b.y}};
  j["balls"] = balls;
  if (!r.cue_ball.empty()) j["cue_ball"] = r.cue_ball;
  return j;
}

ordered_json sceneToJson(const Scene& scene) {
  ordered_json j;
  j["table"] = tableToJson(scene.table);
  j["physics"] = physicsToJson(scene.physics);
  ordered_json balls = ordered_json::array();
  for (const BallState& b : scene.balls) {
    balls.push_back({{"id", b.id}, {"x", b.pos.x}, {"y", b.pos.y}});
  }
  j["balls"] = balls;
  if (scene.shot) {
    const Shot& s = *scene.shot;
    j["shot"] = {{"heading_deg", s.heading_rad * 180.0 / kPi},
                 {"speed", s.speed},
                 {"tip", ordered_json::array({s.tip.x, s.tip.y})},
                 {"elevation_deg", s.elevation_rad * 180.0 / kPi}};
  }
  j["step"] = {{"engine", scene.step.engine.name()}};
  return j;
}

ordered_json fitToJson(const ShotFit& fit, const Recording& shot) {
  ordered_json names;
  for (std::size_t i = 0; i < fit.names.size(); ++i) names[std::to_string(i)] = fit.names[i];
  ordered_json j;
  j["id"] = idToJson(shot);
  j["scene"] = sceneToJson(fit.scene);
  j["names"] = names;
  j["strike_time"] = fit.strike_time;
  j["rmse_m"] = {{"full", fit.rmse.full}, {"early", fit.rmse.early}};
  j["evals"] = fit.evals;
  j["warnings"] = fit.warnings;
  j["unreproduced"] = fit.unreproduced;
  return j;
}

ordered_json refusalToJson(const ShotInput& shot) {
  ordered_json j = ordered_json::object();
  if (!shot.id.is_null()) j["id"] = shot.id;
  j["error"] = shot.refusal;
  return j;
}

namespace {

std::size_t unreproducedBalls(const Calibration& c, const std::vector<std::size_t>& set) {
  std::size_t balls = 0;
  for (std::size_t i : set) balls += c.fits.at(i).unreproduced.size();
  return balls;
}

ordered_json numberOrNull(const std::optional<double>& v) {
  return v ? ordered_json(*v) : ordered_json(nullptr);
}

ordered_json parametersToJson(const Calibration& c) {
  ordered_json out = ordered_json::object();
  for (std::size_t k = 0; k < c.params.size(); ++k) {
    out[c.params[k]] = {{"value", c.values[k]}, {"stderr", numberOrNull(c.uncertainty.stderrs[k])}};
  }
  return out;
}

ordered_json correlationToJson(const CalibrationUncertainty& u) {
  ordered_json rows = ordered_json::array();
  for (const auto& row : u.correlation) {
    ordered_json out = ordered_json::array();
    for (const std::optional<double>& r : row) out.push_back(numberOrNull(r));
    rows.push_back(out);
  }
  return rows;
}

}  // namespace

ordered_json calibrationToJson(const Calibration& c, const std::vector<Recording>& shots) {
  ordered_json j;
  j["physics"] = physicsToJson(c.physics);
  j["parameters"] = parametersToJson(c);
  j["uncertainty"] = {{"method", c.uncertainty.method}, {"resamples", c.uncertainty.resamples}};
  j["correlation"] = correlationToJson(c.uncertainty);
  j["converged"] = c.converged;
  j["convergence"] = c.convergence;
  j["train"] = {{"median_rmse_m", c.train_median},
                {"shots", c.train.size()},
                {"unreproduced_balls", unreproducedBalls(c, c.train)}};
  j["holdout"] = {
      {"median_rmse_m", c.holdout.empty() ? ordered_json(nullptr) : ordered_json(c.holdout_median)},
      {"shots", c.holdout.size()},
      {"unreproduced_balls", unreproducedBalls(c, c.holdout)}};
  ordered_json per_shot = ordered_json::array();
  std::vector<bool> held(shots.size(), false);
  for (std::size_t i : c.holdout) held[i] = true;
  for (std::size_t i = 0; i < c.fits.size(); ++i) {
    ordered_json one = fitToJson(c.fits[i], shots[i]);
    one["set"] = held[i] ? "holdout" : "train";
    per_shot.push_back(one);
  }
  j["per_shot"] = per_shot;
  return j;
}

PhysicsSetter physicsSetter(const std::vector<std::string>& names) {
  return [names](const PhysicsParams& base, const std::vector<double>& values,
                 std::string& why) -> std::optional<PhysicsParams> {
    json physics = json::parse(physicsToJson(base).dump());
    for (std::size_t i = 0; i < names.size(); ++i) {
      const std::size_t dot = names[i].find('.');
      if (dot == std::string::npos) {
        physics[names[i]] = values[i];
      } else {
        physics[names[i].substr(0, dot)][names[i].substr(dot + 1)] = values[i];
      }
    }
    try {
      return parsePhysics(physics);
    } catch (const ParseError& e) {
      why = e.message;
      return std::nullopt;
    }
  };
}

std::variant<std::vector<double>, ParseError> physicsValues(const PhysicsParams& p,
                                                            const std::vector<std::string>& names) {
  const json physics = json::parse(physicsToJson(p).dump());
  std::vector<double> values;
  for (const std::string& name : names) {
    const std::size_t dot = name.find('.');
    const json* v = nullptr;
    if (dot == std::string::npos) {
      if (physics.contains(name)) v = &physics[name];
    } else if (physics.contains(name.substr(0, dot))) {
      const json& outer = physics[name.substr(0, dot)];
      if (outer.is_object() && outer.contains(name.substr(dot + 1))) {
        v = &outer[name.substr(dot + 1)];
      }
    }
    if (!v || !v->is_number()) {
      std::string known;
      for (const auto& item : physics.items()) {
        if (item.value().is_number()) known += (known.empty() ? "" : ", ") + item.key();
        if (item.value().is_object()) {
          for (const auto& inner : item.value().items()) {
            known += (known.empty() ? "" : ", ") + item.key() + "." + inner.key();
          }
        }
      }
      return ParseError{"--params: " + quote(name) +
                        " is no number of these physics (its models read: " + known + ")"};
    }
    values.push_back(v->get<double>());
  }
  return values;
}

}  // namespace nineball::io
