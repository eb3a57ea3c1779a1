#include "app/game/rack_save.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "app/game/game_session.hpp"
#include "app/game/settings.hpp"
#include "app/game/state_file.hpp"
#include "nineball/log.hpp"

namespace nineball::app {
namespace {

constexpr int kVersion = 1;

const char* kindName(TurnInput::Kind k) {
  switch (k) {
    case TurnInput::Kind::PushOut:
      return "push_out";
    case TurnInput::Kind::Decision:
      return "decision";
    case TurnInput::Kind::Shot:
      break;
  }
  return "shot";
}

// Throws nlohmann's errors for a wrong type; rackFromJson turns them into `why`.
TurnInput turnFromJson(const nlohmann::json& t) {
  TurnInput turn;
  const std::string kind = t.at("kind").get<std::string>();
  if (kind == "decision") {
    turn.kind = TurnInput::Kind::Decision;
    turn.shoot = t.at("shoot").get<bool>();
    return turn;
  }
  if (kind != "shot" && kind != "push_out") throw std::invalid_argument("unknown kind " + kind);
  turn.kind = kind == "shot" ? TurnInput::Kind::Shot : TurnInput::Kind::PushOut;
  turn.shot.heading_rad = t.at("heading_rad").get<double>();
  turn.shot.speed = t.at("speed").get<double>();
  turn.shot.tip = {t.at("tip").at(0).get<double>(), t.at("tip").at(1).get<double>()};
  turn.shot.elevation_rad = t.at("elevation_rad").get<double>();
  if (t.contains("cue"))
    turn.cue = Vec2{t["cue"].at(0).get<double>(), t["cue"].at(1).get<double>()};
  if (t.contains("call")) {
    const auto pocket = pocketFromName(t["call"].at("pocket").get<std::string>());
    if (!pocket) throw std::invalid_argument("unknown pocket in a call");
    turn.call = rules::Call{t["call"].at("ball").get<int>(), *pocket};
  }
  return turn;
}

}  // namespace

std::string rackSavePath() {
  return xdgFile("XDG_STATE_HOME", ".local/state", "rack.json");
}

SavedRack saveOf(const GameSession& session, const Opponent& opponent) {
  SavedRack r;
  r.game = session.setup().game;
  r.rules = session.setup().rules;
  r.seed = session.setup().seed;
  r.rack_index = session.rackNumber() - 1;
  r.racks_won = {session.racksWon(0), session.racksWon(1)};
  r.names = {session.seatName(0), session.seatName(1)};
  r.opponent = opponent;
  r.turns = session.rackTurns();
  return r;
}

nlohmann::ordered_json rackToJson(const SavedRack& rack) {
  nlohmann::ordered_json j;
  j["version"] = kVersion;
  j["game"] = rules::gameName(rack.game);
  j["rules"] = rules::ruleSetName(rack.rules);
  j["seed"] = rack.seed;
  j["rack"] = rack.rack_index;
  j["racks_won"] = {rack.racks_won[0], rack.racks_won[1]};
  j["names"] = {rack.names[0], rack.names[1]};
  j["opponent"] = opponentName(rack.opponent);
  // Radians as doubles: JSON numbers keep every bit, degrees would round.
  nlohmann::ordered_json turns = nlohmann::ordered_json::array();
  for (const TurnInput& t : rack.turns) {
    nlohmann::ordered_json o;
    o["kind"] = kindName(t.kind);
    if (t.kind == TurnInput::Kind::Decision) {
      o["shoot"] = t.shoot;
    } else {
      o["heading_rad"] = t.shot.heading_rad;
      o["speed"] = t.shot.speed;
      o["tip"] = {t.shot.tip.x, t.shot.tip.y};
      o["elevation_rad"] = t.shot.elevation_rad;
      if (t.cue) o["cue"] = {t.cue->x, t.cue->y};
      if (t.call) o["call"] = {{"ball", t.call->ball}, {"pocket", pocketName(t.call->pocket)}};
    }
    turns.push_back(o);
  }
  j["turns"] = turns;
  return j;
}

std::optional<SavedRack> rackFromJson(const nlohmann::json& j, std::string& why) {
  try {
    if (j.at("version").get<int>() != kVersion) {
      why = "version " + j["version"].dump() + " is not " + std::to_string(kVersion);
      return std::nullopt;
    }
    SavedRack r;
    const auto rules = rules::ruleSetFromName(j.at("rules").get<std::string>());
    const auto opponent = opponentFromName(j.at("opponent").get<std::string>());
    if (!rules || !opponent) {
      why = "unknown rules or opponent";
      return std::nullopt;
    }
    r.rules = *rules;
    // Saves from before eight- and ten-ball came are nine-ball's.
    const auto game = rules::gameFromName(j.value("game", std::string("nine-ball")));
    if (!game) {
      why = "unknown game";
      return std::nullopt;
    }
    r.game = *game;
    r.opponent = *opponent;
    r.seed = j.at("seed").get<std::uint64_t>();
    r.rack_index = j.at("rack").get<int>();
    for (int i = 0; i < 2; ++i) {
      r.racks_won[i] = j.at("racks_won").at(i).get<int>();
      r.names[i] = j.at("names").at(i).get<std::string>();
    }
    if (r.rack_index < 0 || r.racks_won[0] < 0 || r.racks_won[1] < 0) {
      why = "negative rack or score";
      return std::nullopt;
    }
    for (const auto& t : j.at("turns")) r.turns.push_back(turnFromJson(t));
    return r;
  } catch (const std::exception& e) {
    why = e.what();
    return std::nullopt;
  }
}

bool saveRack(const SavedRack& rack, const std::string& path, std::string& why) {
  return saveStateFile(path, rackToJson(rack).dump(1) + "\n",
                       "neither XDG_STATE_HOME nor HOME is set", why);
}

std::optional<SavedRack> loadRack(const std::string& path) {
  if (path.empty()) return std::nullopt;
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
  std::string why = "not valid JSON";
  auto rack = j.is_discarded() ? std::nullopt : rackFromJson(j, why);
  if (!rack) logger("game")->warn("saved rack {}: {}; not offered", path, why);
  return rack;
}

void forgetRack(const std::string& path) {
  if (!path.empty()) std::remove(path.c_str());
}

void replayRack(GameSession& session, const SavedRack& rack) {
  session.resumeRack(rack.rack_index, rack.racks_won[0], rack.racks_won[1]);
  for (int seat = 0; seat < 2; ++seat) session.setSeatName(seat, rack.names[seat]);
  for (const TurnInput& t : rack.turns) session.playTurn(t);
}

}  // namespace nineball::app
