#include "window/rack_script.hpp"

#include <ctime>

#include "nineball/games.hpp"

namespace nineball::window {

std::optional<nlohmann::ordered_json> rackScript(const GameSession& session) {
  if (session.practice()) return std::nullopt;
  const MatchSetup& setup = session.rackSetup();
  const GameDef& game = gameDef(setup.game);
  nlohmann::ordered_json j;
  j["game"] = game.name;
  j["rules"] = rules::ruleSetName(setup.rules);
  j["seed"] = setup.seed;
  if (game.default_points > 0) j["points"] = setup.points;
  nlohmann::ordered_json turns = nlohmann::ordered_json::array();
  for (const TurnInput& t : session.rackTurns()) {
    nlohmann::ordered_json o;
    if (t.kind == TurnInput::Kind::Decision) {
      const DecisionWords& words = game.decision;
      o["decision"] = t.replace && words.replace ? words.replace : t.shoot ? words.yes : words.no;
      turns.push_back(o);
      continue;
    }
    // Radians as the physics played them: JSON numbers keep every bit, degrees would round.
    o["heading_rad"] = t.shot.heading_rad;
    o["speed"] = t.shot.speed;
    o["tip"] = {t.shot.tip.x, t.shot.tip.y};
    o["elevation_rad"] = t.shot.elevation_rad;
    if (t.kind == TurnInput::Kind::PushOut) o["push_out"] = true;
    if (t.cue) o["cue"] = {t.cue->x, t.cue->y};
    if (t.call) o["call"] = {{"ball", t.call->ball}, {"pocket", pocketName(t.call->pocket)}};
    turns.push_back(o);
  }
  j["turns"] = turns;
  return j;
}

std::string rackScriptName() {
  const std::time_t now = std::time(nullptr);
  char name[64];
  std::strftime(name, sizeof name, "nineball-rack-%Y%m%d-%H%M%S.json", std::localtime(&now));
  return name;
}

}  // namespace nineball::window
