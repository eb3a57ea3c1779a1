#include "io/match_json.hpp"

#include <algorithm>
#include <climits>

#include "io/game_fields.hpp"
#include "io/json_fields.hpp"
#include "io/json_reader.hpp"
#include "io/plan_json.hpp"
#include "io/result_json.hpp"
#include "io/scene_parts.hpp"
#include "io/standing_json.hpp"
#include "nineball/games.hpp"
#include "nineball/scenes.hpp"
#include "nineball/sim.hpp"
#include "nineball/snooker_rack.hpp"

namespace nineball::io {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

// The highest ball a call may name in a pool game (a game with more balls says so:
// GameDef::highest_ball, snooker's black 21).
constexpr int kHighestPoolBall = 15;
// The longest game played to points a script may ask for (UMB distances reach 50).
constexpr int kMostPoints = 100;

Seat parsePlayer(const json& v, const std::string& path) {
  const std::string name = text(v, path);
  if (auto seat = seatFromName(name)) return *seat;
  refuse(path, "unknown player " + quote(name) + " (expected " + seatNamesText() + ")");
}

std::array<Seat, 2> parsePlayers(const json& v) {
  const std::string path = "players";
  expectObject(v, path);
  allowOnly(v, path, {"A", "B"}, "unknown player");
  std::array<Seat, 2> players{};
  if (const json* p = optional(v, "A")) players[0] = parsePlayer(*p, member(path, "A"));
  if (const json* p = optional(v, "B")) players[1] = parsePlayer(*p, member(path, "B"));
  return players;
}

void describeComputerTurn(const ComputerTurn& c, ordered_json& turn) {
  turn["player"] = seatName(ComputerSeat{c.level});
  if (c.input.kind == TurnInput::Kind::Decision) return;
  const Shot& shot = c.input.shot;
  // The exact radians played: a script given heading_rad and elevation_rad plays the turn again
  // bit for bit (the degrees are for reading).
  turn["shot"] = {{"heading_deg", headingDegrees(shot.heading_rad)},
                  {"heading_rad", shot.heading_rad},
                  {"speed", shot.speed},
                  {"tip", {shot.tip.x, shot.tip.y}},
                  {"elevation_rad", shot.elevation_rad}};
  if (c.input.cue) turn["cue"] = {c.input.cue->x, c.input.cue->y};
}

// "race_to" N racks (pool) or frames (snooker), "breaks" "alternate" or "winner".
Race parseRace(const json& doc, rules::Game game) {
  Race race;
  if (const json* p = optional(doc, "race_to")) {
    if (gameDef(game).default_points > 0) {
      refuse("race_to", std::string(rules::gameName(game)) +
                            " is one game played to a number of points (\"points\"), not a race of "
                            "racks");
    }
    race.race_to = integer(*p, "race_to", 1, kLongestRace);
  }
  if (const json* p = optional(doc, "breaks")) {
    if (race.race_to == 0) refuse("breaks", "who breaks the next rack is for a race (\"race_to\")");
    const std::string word = text(*p, "breaks");
    const auto order = breakOrderFromName(word.c_str());
    if (!order)
      refuse("breaks", "unknown order " + quote(word) + " (expected alternate or winner)");
    race.breaks = *order;
  }
  return race;
}

// A standing the game cannot be in is refused naming the first standing key the script gave.
void checkStanding(const MatchSetup& setup, const json& doc) {
  const char* key = "shooter";
  for (const char* k : kStandingKeys) {
    if (optional(doc, k)) {
      key = k;
      break;
    }
  }
  if (!setup.balls) refuse(key, "a rack joined in the middle needs its \"balls\"");
  try {
    const Match probe(setup);
  } catch (const IllegalAction& e) {
    refuse(key, e.what());
  }
}

MatchScript parseMatchDocument(const json& doc) {
  if (!doc.is_object()) refuse("script", "expected an object, found " + describe(doc));
  allowOnly(doc, "",
            {"game", "rules", "seed", "table", "physics", "step", "balls", "players", "turns",
             "points", "race_to", "breaks", "shooter", "ball_in_hand", "fouls", "groups", "score"});
  MatchScript script;
  MatchSetup& setup = script.setup;
  setup.setGame(gameField(doc));
  if (const json* p = optional(doc, "points")) {
    if (gameDef(setup.game).default_points == 0) {
      refuse("points", std::string(rules::gameName(setup.game)) +
                           " is won on a ball, not played to a number of points");
    }
    setup.points = integer(*p, "points", 1, kMostPoints);
  }
  script.race = parseRace(doc, setup.game);
  if (const json* p = optional(doc, "players")) script.players = parsePlayers(*p);
  const bool computer_plays = isComputer(script.players[0]) || isComputer(script.players[1]);
  setup.rules = rulesField(doc, setup.game);
  if (const json* p = optional(doc, "seed")) {
    setup.seed = static_cast<std::uint64_t>(integer(*p, "seed", 0, INT_MAX));
  }
  if (const json* p = optional(doc, "table")) {
    setup.table = parseTable(*p);
    const std::string problem = tableProblem(gameDef(setup.game), setup.table);
    if (!problem.empty()) refuse("table", problem);
  }
  if (const json* p = optional(doc, "physics")) setup.physics = parsePhysics(*p);
  if (const json* p = optional(doc, "step")) setup.step = parseStep(*p);
  double cue_mass = setup.physics.ball_mass;
  Scene check;
  check.table = setup.table;
  check.physics = setup.physics;
  check.step = setup.step;
  if (const json* p = optional(doc, "balls")) {
    setup.balls = parseBalls(*p, setup.physics);
    check.balls = *setup.balls;
    if (auto problem = validateScene(check)) throw ParseError{*problem};
    for (const BallState& b : *setup.balls) {
      if (b.id == kCueBall && b.mass) cue_mass = *b.mass;
    }
    checkGameBalls(setup.game, *setup.balls);
  } else {
    // The rack the match would set up must fit the table like any given balls.
    check.balls = setup.openingBalls();
    if (auto problem = validateScene(check)) {
      refuse("table", std::string("too small for the ") + rules::gameName(setup.game) +
                          " rack and the cue ball (" + *problem + ")");
    }
  }
  setup.standing = parseStanding(doc);
  if (setup.standing) checkStanding(setup, doc);
  static const json kNoTurns = json::array();
  const json& turns =
      computer_plays && !optional(doc, "turns") ? kNoTurns : required(doc, "", "turns");
  if (!turns.is_array()) refuse("turns", "expected an array of turns, found " + describe(turns));
  for (std::size_t i = 0; i < turns.size(); ++i) {
    script.turns.push_back(parseTurn(turns[i], element("turns", i), cue_mass, setup.game));
  }
  return script;
}

ordered_json winnerJson(const std::optional<rules::Player>& w) {
  return w ? ordered_json(rules::playerName(*w)) : ordered_json(nullptr);
}

ordered_json groupJson(const std::optional<rules::Group>& g) {
  return g ? ordered_json(rules::groupName(*g)) : ordered_json(nullptr);
}

ordered_json playerScoreJson(const PlayerScore& p) {
  return {{"points", p.points},
          {"innings", p.innings},
          {"run", p.run},
          {"average", p.innings > 0 ? static_cast<double>(p.points) / p.innings : 0.0},
          {"high_run", p.high_run}};
}

ordered_json scoreJson(const Score& s) {
  return {{"A", playerScoreJson(s.a)}, {"B", playerScoreJson(s.b)}};
}

const char* decisionWord(const TurnRecord& t, const GameDef& def) {
  if (t.answered == rules::Decision::RerackOrPlayOn) return t.shoot ? "play-on" : "rerack";
  if (t.replace) return def.decision.replace;
  if (t.answered == rules::Decision::PlayOrPutBack ||
      t.answered == rules::Decision::PlayPutBackOrReplace) {
    return t.shoot ? def.decision.yes : def.decision.no;
  }
  return t.shoot ? "shoot" : "pass";
}

ordered_json snookerScoreJson(const Score& s) {
  auto one = [](const PlayerScore& p) {
    return ordered_json{{"points", p.points}, {"break", p.run}, {"high_break", p.high_run}};
  };
  return {{"A", one(s.a)}, {"B", one(s.b)}};
}

// The words the player to move may answer with now, or null when no choice waits.
ordered_json choicesJson(const rules::Verdict& v, const GameDef& def) {
  if (v.decision == rules::Decision::PlayOrPutBack) return {def.decision.yes, def.decision.no};
  if (v.decision == rules::Decision::PlayPutBackOrReplace) {
    return {def.decision.yes, def.decision.no, def.decision.replace};
  }
  return nullptr;
}

// Snooker's part of a turn (docs/cli.md, "nineball match", snooker).
void describeSnookerTurn(const TurnRecord& t, ordered_json& turn) {
  const rules::Verdict& v = t.verdict;
  const GameDef& def = gameDef(rules::Game::Snooker);
  if (t.kind != TurnInput::Kind::Decision) {
    turn["nominated"] = v.nominated == 0 ? ordered_json(nullptr) : ordered_json(v.nominated);
    turn["free_ball"] = v.free_ball;
    turn["miss"] = v.miss;
    turn["points"] = v.legal() ? v.points[0] + v.points[1] : 0;
    turn["penalty"] = v.legal() ? 0 : v.points[0] + v.points[1];
    turn["choices"] = choicesJson(v, def);
    turn["black_respotted"] = v.black_respotted;
  }
  const PlayerScore& striker = t.verdict.next == rules::Player::A ? t.score.a : t.score.b;
  turn["break"] = striker.run;
  turn["score"] = snookerScoreJson(t.score);
  turn["points_remaining"] = t.points_remaining;
  turn["free_ball_next"] = t.free_ball_next;
}

}  // namespace

namespace {

rules::Call parseCall(const json& v, const std::string& path, rules::Game game) {
  expectObject(v, path);
  allowOnly(v, path, {"ball", "pocket"});
  rules::Call call;
  const int highest = std::max(kHighestPoolBall, gameDef(game).highest_ball);
  call.ball = integer(required(v, path, "ball"), member(path, "ball"), 1, highest);
  const std::string name = text(required(v, path, "pocket"), member(path, "pocket"));
  const auto pocket = pocketFromName(name);
  if (!pocket) {
    refuse(member(path, "pocket"),
           "unknown pocket " + quote(name) +
               " (expected \"top-left\", \"top-side\", \"top-right\", \"bottom-right\", "
               "\"bottom-side\" or \"bottom-left\")");
  }
  call.pocket = *pocket;
  return call;
}

}  // namespace

TurnInput parseTurn(const json& v, const std::string& path, double cue_mass, rules::Game game) {
  expectObject(v, path);
  TurnInput turn;
  if (const json* d = optional(v, "decision")) {
    allowOnly(v, path, {"decision"});
    const std::string where = member(path, "decision");
    turn.kind = TurnInput::Kind::Decision;
    const std::string word = text(*d, where);
    const char* replace = gameDef(game).decision.replace;
    if (replace && word == replace) {
      turn.replace = true;
      turn.shoot = false;
      return turn;
    }
    turn.shoot = decisionField(word, game, where);
    return turn;
  }
  allowOnly(v, path,
            {"heading_deg", "heading_rad", "speed", "force", "contact_time", "tip", "elevation_deg",
             "elevation_rad", "cue", "push_out", "call"});
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
  if (const json* c = optional(v, "call")) turn.call = parseCall(*c, member(path, "call"), game);
  return turn;
}

ordered_json turnToJson(const TurnInput& turn, rules::Game game) {
  ordered_json j;
  if (turn.kind == TurnInput::Kind::Decision) {
    const DecisionWords& words = gameDef(game).decision;
    j["decision"] = turn.replace && words.replace ? words.replace
                    : turn.shoot                  ? words.yes
                                                  : words.no;
    return j;
  }
  j["heading_deg"] = turn.shot.heading_rad * 180.0 / kPi;
  j["speed"] = turn.shot.speed;
  j["tip"] = {turn.shot.tip.x, turn.shot.tip.y};
  j["elevation_deg"] = turn.shot.elevation_rad * 180.0 / kPi;
  if (turn.kind == TurnInput::Kind::PushOut) j["push_out"] = true;
  if (turn.cue) j["cue"] = {turn.cue->x, turn.cue->y};
  if (turn.call) j["call"] = {{"ball", turn.call->ball}, {"pocket", pocketName(turn.call->pocket)}};
  return j;
}

MatchScriptResult parseMatchScript(std::string_view text) {
  try {
    return parseMatchDocument(readJson(text));
  } catch (const ParseError& e) {
    return e;
  }
}

nlohmann::ordered_json matchResultToJson(const std::vector<TurnRecord>& turns,
                                         const rules::Rack& rack,
                                         const std::vector<BallState>& balls,
                                         const std::vector<std::optional<ComputerTurn>>& computer) {
  ordered_json doc;
  ordered_json list = ordered_json::array();
  rules::Groups groups;
  for (std::size_t i = 0; i < turns.size(); ++i) {
    const TurnRecord& t = turns[i];
    const rules::Verdict& v = t.verdict;
    ordered_json turn;
    turn["shooter"] = rules::playerName(t.shooter);
    if (i < computer.size() && computer[i]) describeComputerTurn(*computer[i], turn);
    if (t.kind == TurnInput::Kind::Decision) {
      turn["decision"] = decisionWord(t, gameDef(rack.game()));
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
    if (t.call) {
      turn["call"] = {{"ball", t.call->ball}, {"pocket", pocketName(t.call->pocket)}};
    }
    if (gameDef(rack.game()).pot_not_as_called_passes) {
      turn["call_breach"] = v.call_breach == rules::Foul::None
                                ? ordered_json(nullptr)
                                : ordered_json(rules::foulName(v.call_breach));
    }
    if (gameDef(rack.game()).default_points > 0 && t.kind != TurnInput::Kind::Decision) {
      turn["point"] = v.points[0] + v.points[1] > 0;
      turn["cushions"] = v.cushions;
      turn["score"] = scoreJson(t.score);
    }
    if (gameDef(rack.game()).snookers) describeSnookerTurn(t, turn);
    if (gameDef(rack.game()).groups) {
      // A decision changes no group: it shows those of the shot before.
      if (t.kind != TurnInput::Kind::Decision) groups = v.groups;
      turn["groups"] = {{"A", groupJson(groups.a)}, {"B", groupJson(groups.b)}};
    }
    list.push_back(turn);
  }
  doc["turns"] = list;
  doc["winner"] = winnerJson(rack.winner());
  if (gameDef(rack.game()).default_points > 0) {
    doc["points"] = rack.targetPoints();
    doc["draw"] = rack.drawn();
    doc["score"] = scoreJson(scoreOf(rack));
  }
  if (gameDef(rack.game()).snookers) {
    doc["score"] = snookerScoreJson(scoreOf(rack));
    doc["points_remaining"] = rack.pointsRemaining();
    doc["snookers_required"] = {{"A", rules::snookersRequired(rack, rules::Player::A)},
                                {"B", rules::snookersRequired(rack, rules::Player::B)}};
  }
  ordered_json ball_list = ordered_json::array();
  for (const BallState& b : balls) ball_list.push_back(ballToJson(b));
  doc["balls"] = ball_list;
  return doc;
}

}  // namespace nineball::io
