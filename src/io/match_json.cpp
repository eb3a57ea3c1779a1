#include "io/match_json.hpp"

#include <algorithm>
#include <climits>

#include "io/json_fields.hpp"
#include "io/json_reader.hpp"
#include "io/result_json.hpp"
#include "io/scene_parts.hpp"
#include "nineball/sim.hpp"

namespace nineball::io {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

TurnInput parseTurn(const json& v, const std::string& path, double cue_mass) {
  expectObject(v, path);
  TurnInput turn;
  if (const json* d = optional(v, "decision")) {
    allowOnly(v, path, {"decision"});
    const std::string choice = text(*d, member(path, "decision"));
    if (choice != "shoot" && choice != "pass") {
      refuse(member(path, "decision"), "expected \"shoot\" or \"pass\", found " + quote(choice));
    }
    turn.kind = TurnInput::Kind::Decision;
    turn.shoot = choice == "shoot";
    return turn;
  }
  allowOnly(v, path, {"heading_deg", "speed", "force", "contact_time", "tip", "cue", "push_out"});
  if (const json* p = optional(v, "push_out")) {
    if (!p->is_boolean())
      refuse(member(path, "push_out"), "expected true or false, found " + describe(*p));
    if (p->get<bool>()) turn.kind = TurnInput::Kind::PushOut;
  }
  turn.shot = parseShotFields(v, path, cue_mass);
  if (const json* c = optional(v, "cue")) {
    const std::string cpath = member(path, "cue");
    if (!c->is_array() || c->size() != 2) {
      refuse(cpath, "expected [x, y] in metres, found " + describe(*c));
    }
    turn.cue = Vec2{number((*c)[0], element(cpath, 0)), number((*c)[1], element(cpath, 1))};
  }
  return turn;
}

MatchScript parseDocument(const json& doc) {
  if (!doc.is_object()) refuse("script", "expected an object, found " + describe(doc));
  allowOnly(doc, "", {"rules", "seed", "table", "physics", "step", "balls", "turns"});
  MatchScript script;
  MatchSetup& setup = script.setup;
  if (const json* p = optional(doc, "rules")) {
    const std::string name = text(*p, "rules");
    const auto rules = rules::ruleSetFromName(name);
    if (!rules)
      refuse("rules", "unknown rules " + quote(name) + " (expected \"wpa\" or \"paper\")");
    setup.rules = *rules;
  }
  if (const json* p = optional(doc, "seed")) {
    setup.seed = static_cast<std::uint64_t>(integer(*p, "seed", 0, INT_MAX));
  }
  if (const json* p = optional(doc, "table")) setup.table = parseTable(*p);
  if (const json* p = optional(doc, "physics")) setup.physics = parsePhysics(*p);
  if (const json* p = optional(doc, "step")) setup.step = parseStep(*p);
  double cue_mass = setup.physics.ball_mass;
  if (const json* p = optional(doc, "balls")) {
    setup.balls = parseBalls(*p);
    Scene check;
    check.table = setup.table;
    check.physics = setup.physics;
    check.step = setup.step;
    check.balls = *setup.balls;
    if (auto problem = validateScene(check)) throw ParseError{*problem};
    for (const BallState& b : *setup.balls) {
      if (b.id == kCueBall && b.mass) cue_mass = *b.mass;
    }
  }
  const json& turns = required(doc, "", "turns");
  if (!turns.is_array()) refuse("turns", "expected an array of turns, found " + describe(turns));
  for (std::size_t i = 0; i < turns.size(); ++i) {
    script.turns.push_back(parseTurn(turns[i], element("turns", i), cue_mass));
  }
  return script;
}

ordered_json winnerJson(const std::optional<rules::Player>& w) {
  return w ? ordered_json(rules::playerName(*w)) : ordered_json(nullptr);
}

}  // namespace

MatchScriptResult parseMatchScript(std::string_view text) {
  try {
    return parseDocument(readJson(text));
  } catch (const ParseError& e) {
    return e;
  }
}

nlohmann::ordered_json matchResultToJson(const std::vector<TurnRecord>& turns,
                                         const rules::Rack& rack,
                                         const std::vector<BallState>& balls) {
  ordered_json doc;
  ordered_json list = ordered_json::array();
  for (const TurnRecord& t : turns) {
    const rules::Verdict& v = t.verdict;
    ordered_json turn;
    turn["shooter"] = rules::playerName(t.shooter);
    if (t.kind == TurnInput::Kind::Decision) {
      turn["decision"] = v.next == t.shooter ? "shoot" : "pass";
    } else if (t.kind == TurnInput::Kind::PushOut) {
      turn["push_out"] = true;
    }
    turn["result"] = v.legal() ? "legal" : "foul";
    turn["foul"] = v.legal() ? ordered_json(nullptr) : ordered_json(rules::foulName(v.foul));
    turn["pocketed"] = v.pocketed;
    turn["next"] = rules::playerName(v.next);
    turn["ball_on"] = t.ball_on;
    turn["ball_in_hand"] = v.ball_in_hand;
    turn["winner"] = winnerJson(v.winner);
    list.push_back(turn);
  }
  doc["turns"] = list;
  doc["winner"] = winnerJson(rack.winner());
  ordered_json ball_list = ordered_json::array();
  for (const BallState& b : balls) ball_list.push_back(ballToJson(b));
  doc["balls"] = ball_list;
  return doc;
}

}  // namespace nineball::io
