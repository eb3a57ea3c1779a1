#include "io/plan_json.hpp"

#include <algorithm>
#include <cmath>

#include "io/game_fields.hpp"
#include "io/json_fields.hpp"
#include "io/json_reader.hpp"
#include "io/scene_json.hpp"
#include "nineball/games.hpp"

namespace nineball::io {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

PlanScene parsePlanDocument(json doc) {
  if (!doc.is_object()) refuse("scene", "expected an object, found " + describe(doc));
  allowOnly(doc, "",
            {"table", "physics", "balls", "shot", "until", "step", "game", "rules", "ball_in_hand",
             "level"});
  PlanScene plan;
  const rules::Game game = gameField(doc);
  const rules::RuleSet rule_set = rulesField(doc, game);
  bool in_hand = false;
  if (const json* p = optional(doc, "ball_in_hand")) {
    if (!p->is_boolean()) refuse("ball_in_hand", "expected true or false, found " + describe(*p));
    in_hand = p->get<bool>();
  }
  if (const json* p = optional(doc, "level")) {
    const std::string name = text(*p, "level");
    const auto found = ai::levelFromName(name);
    if (!found) {
      refuse("level", "unknown level " + quote(name) + " (expected " + ai::levelNamesText() + ")");
    }
    plan.level = *found;
  }
  // The game's own equipment unless the scene brings its own, as a match script gets it.
  if (!optional(doc, "table")) doc["table"] = gameDef(game).tables.front();
  if (!optional(doc, "physics")) doc["physics"] = {{"preset", gameDef(game).physics}};
  for (const char* key : {"game", "rules", "ball_in_hand", "level"}) doc.erase(key);
  SceneResult parsed = sceneFromJson(doc);
  if (const auto* refused = std::get_if<ParseError>(&parsed)) throw *refused;
  const Scene& scene = std::get<Scene>(parsed);
  const std::string table_problem = tableProblem(gameDef(game), scene.table);
  if (!table_problem.empty()) refuse("table", table_problem);

  std::vector<int> object_balls;
  bool has_cue = false;
  for (const BallState& b : scene.balls) {
    if (b.id == kCueBall) {
      has_cue = true;
    } else {
      object_balls.push_back(b.id);
    }
  }
  checkGameBalls(game, scene.balls);
  if (!has_cue && !in_hand) {
    refuse("balls", "needs a cue ball (id 0) unless \"ball_in_hand\" is true");
  }
  ai::PlanInput& in = plan.input;
  in.table = scene.table;
  in.physics = scene.physics;
  in.step = scene.step;
  in.balls = scene.balls;
  in.rack = rules::Rack(game, rule_set, object_balls, false);
  in.cue_in_hand = in_hand;
  in.cue_area = gameDef(game).in_hand_area;
  return plan;
}

}  // namespace

double headingDegrees(double rad) {
  double deg = std::remainder(radToDeg(rad), 360.0);
  if (deg <= -180.0) deg += 360.0;
  return deg;
}

PlanSceneResult parsePlanScene(std::string_view text) {
  const bool blank = std::all_of(text.begin(), text.end(), [](char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
  });
  if (blank) return ParseError{"invalid JSON: empty input"};
  try {
    return parsePlanDocument(readJson(text));
  } catch (const ParseError& e) {
    return e;
  }
}

ordered_json planToJson(const ai::Plan& plan) {
  ordered_json doc;
  const Shot& shot = plan.turn.shot;
  doc["heading_deg"] = headingDegrees(shot.heading_rad);
  doc["speed"] = shot.speed;
  doc["tip"] = {shot.tip.x, shot.tip.y};
  // A raised cue (a jump, carom's swerve) is part of the shot; a level one is left unsaid.
  if (shot.elevation_rad > 0.0) doc["elevation_deg"] = radToDeg(shot.elevation_rad);
  if (plan.turn.cue) doc["cue"] = {plan.turn.cue->x, plan.turn.cue->y};
  if (plan.turn.call) {
    doc["call"] = {{"ball", plan.turn.call->ball}, {"pocket", pocketName(plan.turn.call->pocket)}};
  }
  return doc;
}

}  // namespace nineball::io
