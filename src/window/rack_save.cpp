#include "window/rack_save.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "common/log.hpp"
#include "nineball/games.hpp"
#include "window/game_session.hpp"
#include "window/player_name.hpp"
#include "window/settings.hpp"
#include "window/state_file.hpp"

namespace nineball::window {
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

// A saved rack is checked as strictly as a match script: what the game's own controls can
// give, nothing more (an edited or damaged file must not reach the physics or the rules).
constexpr int kMaxRackIndex = 1000000;
constexpr std::size_t kMaxSavedTurns = 2000;

void expect(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

void checkTurn(const TurnInput& t, const std::string& at) {
  if (t.kind == TurnInput::Kind::Decision) return;
  const Shot& s = t.shot;
  expect(std::isfinite(s.heading_rad) && std::abs(s.heading_rad) <= 8.0,
         at + ".heading_rad: not a heading");
  expect(s.speed >= GameSession::kMinSpeed && s.speed <= GameSession::kMaxSpeed,
         at + ".speed: the cue gives 0.1 to 12 m/s");
  expect(std::isfinite(s.tip.x) && std::isfinite(s.tip.y) && length(s.tip) <= GameSession::kMaxTip,
         at + ".tip: past the cue's reach (half the radius)");
  expect(s.elevation_rad >= 0.0 && s.elevation_rad <= degToRad(GameSession::kMaxElevationDeg),
         at + ".elevation_rad: the cue tilts 0 to 60 degrees");
  if (t.cue) {
    expect(std::isfinite(t.cue->x) && std::isfinite(t.cue->y) && std::abs(t.cue->x) < 10.0 &&
               std::abs(t.cue->y) < 10.0,
           at + ".cue: not a place on the table");
  }
  // Snooker's colours are 16-21: the highest ball any game calls or nominates.
  if (t.call) expect(t.call->ball >= 1 && t.call->ball <= 21, at + ".call.ball: no such ball");
}

TurnInput turnFromJson(const nlohmann::json& t);

std::vector<TurnInput> turnsFromJson(const nlohmann::json& list, const std::string& path,
                                     std::size_t most) {
  expect(list.is_array() && list.size() <= most, path + ": not a rack's turns");
  std::vector<TurnInput> turns;
  for (const auto& t : list) {
    turns.push_back(turnFromJson(t));
    checkTurn(turns.back(), path + "[" + std::to_string(turns.size() - 1) + "]");
  }
  return turns;
}

nlohmann::ordered_json turnsToJson(const std::vector<TurnInput>& turns) {
  // Radians as doubles: JSON numbers keep every bit, degrees would round.
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const TurnInput& t : turns) {
    nlohmann::ordered_json o;
    o["kind"] = kindName(t.kind);
    if (t.kind == TurnInput::Kind::Decision) {
      o["shoot"] = t.shoot;
      if (t.replace) o["replace"] = true;
    } else {
      o["heading_rad"] = t.shot.heading_rad;
      o["speed"] = t.shot.speed;
      o["tip"] = {t.shot.tip.x, t.shot.tip.y};
      o["elevation_rad"] = t.shot.elevation_rad;
      if (t.cue) o["cue"] = {t.cue->x, t.cue->y};
      if (t.call) o["call"] = {{"ball", t.call->ball}, {"pocket", pocketName(t.call->pocket)}};
    }
    list.push_back(o);
  }
  return list;
}

// Throws nlohmann's errors for a wrong type; rackFromJson turns them into `why`.
TurnInput turnFromJson(const nlohmann::json& t) {
  TurnInput turn;
  const std::string kind = t.at("kind").get<std::string>();
  if (kind == "decision") {
    turn.kind = TurnInput::Kind::Decision;
    turn.shoot = t.at("shoot").get<bool>();
    // Snooker's third answer after a miss (absent: not chosen).
    turn.replace = t.contains("replace") && t.at("replace").get<bool>();
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

SavedRack saveOf(const GameSession& session, const Seat& opponent) {
  SavedRack r;
  r.game = session.setup().game;
  r.rules = session.setup().rules;
  r.seed = session.setup().seed;
  r.rack_index = session.rackNumber() - 1;
  r.racks_won = {session.racksWon(0), session.racksWon(1)};
  r.best_of = session.bestOf();
  r.names = {session.seatName(0), session.seatName(1)};
  r.opponent = opponent;
  r.turns = session.rackTurns();
  r.breaks = session.breaks();
  r.breaker = session.seatOf(rules::Player::A);
  if (session.bestOf() > 0 && session.matchKnown() && !session.fixedSeats()) {
    r.first_rack = session.matchFirstRack();
    r.match_turns = session.matchTurns();
  }
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
  if (rack.best_of > 0) j["best_of"] = rack.best_of;
  j["names"] = {rack.names[0], rack.names[1]};
  j["opponent"] = seatName(rack.opponent);
  j["breaks"] = breakOrderName(rack.breaks);
  if (rack.breaker) j["breaker"] = *rack.breaker;
  j["turns"] = turnsToJson(rack.turns);
  if (rack.first_rack >= 0) {
    j["match"] = {{"first_rack", rack.first_rack}, {"turns", turnsToJson(rack.match_turns)}};
  }
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
    const auto opponent = seatFromName(j.at("opponent").get<std::string>());
    if (!rules || !opponent) {
      why = "unknown rules or opponent";
      return std::nullopt;
    }
    r.rules = *rules;
    // Saves from before games were named are the default game's.
    const auto game = gameNamed(j.value("game", std::string(defaultGame().name)));
    if (!game) {
      why = "unknown game";
      return std::nullopt;
    }
    r.game = game->id;
    expect(gameDef(r.game).playedBy(r.rules), rulesOnlyFor(r.rules));
    r.opponent = *opponent;
    r.seed = j.at("seed").get<std::uint64_t>();
    r.rack_index = j.at("rack").get<int>();
    expect(r.rack_index >= 0 && r.rack_index <= kMaxRackIndex, "rack: not a rack number");
    for (int i = 0; i < 2; ++i) {
      r.racks_won[i] = j.at("racks_won").at(i).get<int>();
      expect(r.racks_won[i] >= 0 && r.racks_won[i] <= r.rack_index + 1,
             "racks_won: more racks won than played");
      const auto name = playerName(j.at("names").at(i).get<std::string>());
      expect(name.has_value(), "names: empty or not valid UTF-8");
      r.names[i] = *name;
    }
    // Saves from before matches of frames have none.
    r.best_of = j.value("best_of", 0);
    expect(r.best_of >= 0 && r.best_of <= kMaxRackIndex, "best_of: not a match length");
    r.turns = turnsFromJson(j.at("turns"), "turns", kMaxSavedTurns);
    // Saves from before the break order was kept: in turn.
    if (j.contains("breaks")) {
      const auto order = breakOrderFromName(j.at("breaks").get<std::string>().c_str());
      expect(order.has_value(), "breaks: not alternate or winner");
      r.breaks = *order;
    }
    if (j.contains("breaker")) {
      r.breaker = j.at("breaker").get<int>();
      expect(*r.breaker == 0 || *r.breaker == 1, "breaker: not a seat");
    }
    if (j.contains("match")) {
      const auto& match = j.at("match");
      r.first_rack = match.at("first_rack").get<int>();
      expect(r.first_rack >= 0 && r.first_rack <= r.rack_index, "match.first_rack: not a rack");
      expect(r.best_of > 0, "match: a rack without a match length");
      const std::size_t racks = static_cast<std::size_t>(r.best_of);
      r.match_turns = turnsFromJson(match.at("turns"), "match.turns", racks * kMaxSavedTurns);
    }
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
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  std::string text, why;
  std::optional<SavedRack> rack;
  if (readStateFile(path, text, why)) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    why = "not valid JSON";
    if (!j.is_discarded()) rack = rackFromJson(j, why);
  }
  if (!rack) {
    // Kept, it would be refused again at every start.
    logger("game")->warn("saved rack {}: {}; not offered, and deleted", path, printable(why));
    forgetRack(path);
  }
  return rack;
}

void forgetRack(const std::string& path) {
  if (!path.empty()) std::remove(path.c_str());
}

void replayRack(GameSession& session, const SavedRack& rack) {
  session.setBestOf(rack.best_of);
  session.setBreaks(rack.breaks);
  for (int seat = 0; seat < 2; ++seat) session.setSeatName(seat, rack.names[seat]);
  if (rack.first_rack < 0) {
    session.resumeRack(rack.rack_index, rack.racks_won[0], rack.racks_won[1], rack.breaker);
    for (const TurnInput& t : rack.turns) session.playTurn(t);
    return;
  }
  session.startMatchAt(rack.first_rack);
  for (const TurnInput& t : rack.match_turns) session.playTurn(t);
  // Saved as the next rack was racked, before its break.
  if (session.phase() == Phase::GameOver && session.rackNumber() - 1 < rack.rack_index) {
    session.rematch();
  }
  const bool same =
      session.rackNumber() - 1 == rack.rack_index && session.racksWon(0) == rack.racks_won[0] &&
      session.racksWon(1) == rack.racks_won[1] && session.rackTurns().size() == rack.turns.size();
  if (!same) throw IllegalAction("the saved match does not come back to its rack and score");
}

}  // namespace nineball::window
