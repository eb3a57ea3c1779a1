#include "window/rack_script.hpp"

#include <ctime>

#include "nineball/games.hpp"

namespace nineball::window {
namespace {

using nlohmann::ordered_json;

ordered_json turnsJson(const std::vector<TurnInput>& turns, const GameDef& game) {
  ordered_json list = ordered_json::array();
  for (const TurnInput& t : turns) {
    ordered_json o;
    if (t.kind == TurnInput::Kind::Decision) {
      const DecisionWords& words = game.decision;
      o["decision"] = t.replace && words.replace ? words.replace : t.shoot ? words.yes : words.no;
      list.push_back(o);
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
    list.push_back(o);
  }
  return list;
}

// The script's own setup, the keys this file writes left out, in the order a person reads them.
ordered_json setupPart(const nlohmann::json& setup) {
  ordered_json part = ordered_json::object();
  if (!setup.is_object()) return part;
  for (const auto& [key, value] : setup.items()) {
    if (key == "game" || key == "rules" || key == "seed" || key == "points" || key == "race_to" ||
        key == "breaks" || key == "turns" || key == "players")
      continue;
    part[key] = value;
  }
  return part;
}

}  // namespace

bool savesMatch(const GameSession& session) {
  return !session.practice() && session.bestOf() > 0 && session.matchKnown() &&
         !session.fixedSeats();
}

std::optional<ordered_json> gameScript(const GameSession& session, const nlohmann::json& setup) {
  if (session.practice()) return std::nullopt;
  const bool match = savesMatch(session);
  const MatchSetup& rack = session.rackSetup();
  const GameDef& game = gameDef(rack.game);
  ordered_json j;
  j["game"] = game.name;
  j["rules"] = rules::ruleSetName(rack.rules);
  j["seed"] = match ? session.matchSeed() : rack.seed;
  if (game.default_points > 0) j["points"] = rack.points;
  if (match) {
    j["race_to"] = framesToWinMatch(session.bestOf());
    j["breaks"] = breakOrderName(session.breaks());
  }
  ordered_json part = setupPart(setup);
  // A layout is the first rack's: the racks after it are racked afresh.
  const bool first_rack_laid_out = match ? session.matchFirstRack() == 0 : rack.balls.has_value();
  if (!first_rack_laid_out) part.erase("balls");
  j.update(part);
  j["turns"] = turnsJson(match ? session.matchTurns() : session.rackTurns(), game);
  return j;
}

std::string gameScriptName(bool match) {
  const std::time_t now = std::time(nullptr);
  char name[64];
  std::strftime(name, sizeof name,
                match ? "nineball-match-%Y%m%d-%H%M%S.json" : "nineball-rack-%Y%m%d-%H%M%S.json",
                std::localtime(&now));
  return name;
}

}  // namespace nineball::window
