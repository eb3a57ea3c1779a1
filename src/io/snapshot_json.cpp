#include "io/snapshot_json.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#include "io/json_fields.hpp"
#include "io/result_json.hpp"
#include "nineball/table.hpp"

namespace nineball::io {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

// Speeds and spins of balls between turns are zero; a snapshot is still read whole, within
// what any shot could give.
constexpr double kMostSpeed = 100.0;   // m/s
constexpr double kMostSpin = 10000.0;  // rad/s
constexpr int kMostCount = 1000000;    // scores, innings, fouls and runs

// The result's ball (the pocket by name) and its mass, which a result leaves out.
ordered_json ballsToJson(const std::vector<BallState>& balls) {
  ordered_json out = ordered_json::array();
  for (const BallState& b : balls) {
    ordered_json j = ballToJson(b);
    j["mass"] = b.mass ? ordered_json(*b.mass) : ordered_json(nullptr);
    out.push_back(j);
  }
  return out;
}

ordered_json intsToJson(const std::vector<int>& v) {
  ordered_json out = ordered_json::array();
  for (int x : v) out.push_back(x);
  return out;
}

ordered_json optionalInt(bool has, int value) {
  return has ? ordered_json(value) : ordered_json(nullptr);
}

bool flag(const json& obj, const std::string& path, const char* key) {
  const json& v = required(obj, path, key);
  if (!v.is_boolean()) refuse(member(path, key), "expected true or false, found " + describe(v));
  return v.get<bool>();
}

int count(const json& obj, const std::string& path, const char* key) {
  return integer(required(obj, path, key), member(path, key), 0, kMostCount);
}

void pairOf(const json& obj, const std::string& path, const char* key, int (&out)[2]) {
  const json& v = required(obj, path, key);
  const std::string at = member(path, key);
  if (!v.is_array() || v.size() != 2) refuse(at, "expected [A, B], found " + describe(v));
  for (std::size_t i = 0; i < 2; ++i) out[i] = integer(v[i], element(at, i), 0, kMostCount);
}

// Ball numbers, each one of the match's balls, sorted and without repeats.
std::vector<int> ballNumbers(const json& obj, const std::string& path, const char* key,
                             const std::vector<BallState>& like) {
  const json& v = required(obj, path, key);
  const std::string at = member(path, key);
  if (!v.is_array() || v.size() > like.size()) refuse(at, "expected a list of balls");
  std::vector<int> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const int id = integer(v[i], element(at, i), 0, INT_MAX);
    const bool known =
        std::any_of(like.begin(), like.end(), [id](const BallState& b) { return b.id == id; });
    if (!known) refuse(element(at, i), "no ball " + std::to_string(id) + " in this match");
    if (!out.empty() && id <= out.back()) refuse(element(at, i), "not sorted or repeated");
    out.push_back(id);
  }
  return out;
}

std::vector<BallState> parseBallList(const json& v, const std::string& path,
                                     const std::vector<BallState>& like, double bound, bool whole) {
  if (!v.is_array()) refuse(path, "expected an array of balls, found " + describe(v));
  if (whole ? v.size() != like.size() : v.size() > like.size()) {
    refuse(path, "expected the match's " + std::to_string(like.size()) + " balls");
  }
  std::vector<BallState> balls;
  const Bounds place = Bounds::closed(-bound, bound);
  const Bounds speed = Bounds::closed(-kMostSpeed, kMostSpeed);
  const Bounds spin = Bounds::closed(-kMostSpin, kMostSpin);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const json& b = v[i];
    const std::string at = element(path, i);
    expectObject(b, at);
    allowOnly(b, at, {"id", "x", "y", "vx", "vy", "z", "vz", "w", "mass", "pocket", "off_table"});
    BallState ball;
    ball.id = integer(required(b, at, "id"), member(at, "id"), 0, INT_MAX);
    if (whole && ball.id != like[i].id) {
      refuse(member(at, "id"), "expected ball " + std::to_string(like[i].id));
    }
    ball.pos = {number(required(b, at, "x"), member(at, "x"), place),
                number(required(b, at, "y"), member(at, "y"), place)};
    ball.vel = {number(required(b, at, "vx"), member(at, "vx"), speed),
                number(required(b, at, "vy"), member(at, "vy"), speed)};
    // A ball's height came with the airborne balls: a state written before has none.
    if (const json* z = optional(b, "z")) {
      ball.z = number(*z, member(at, "z"), Bounds::closed(0.0, limits::kMaxBallHeight));
    }
    if (const json* vz = optional(b, "vz")) ball.vz = number(*vz, member(at, "vz"), speed);
    const json& w = required(b, at, "w");
    const std::string wat = member(at, "w");
    if (!w.is_array() || w.size() != 3) refuse(wat, "expected [wx, wy, wz], found " + describe(w));
    ball.w = {number(w[0], element(wat, 0), spin), number(w[1], element(wat, 1), spin),
              number(w[2], element(wat, 2), spin)};
    const json& mass = required(b, at, "mass");
    if (!mass.is_null()) ball.mass = number(mass, member(at, "mass"), Bounds::positive(10.0));
    const json& pocket = required(b, at, "pocket");
    if (!pocket.is_null()) {
      const std::string name = text(pocket, member(at, "pocket"));
      ball.pocket = pocketFromName(name);
      if (!ball.pocket) refuse(member(at, "pocket"), "unknown pocket " + quote(name));
    }
    if (const json* off = optional(b, "off_table")) {
      if (!off->is_boolean()) refuse(member(at, "off_table"), "expected true or false");
      ball.off_table = off->get<bool>();
      if (ball.off_table && ball.pocket) {
        refuse(member(at, "pocket"), "a ball off the table lies in no pocket");
      }
      if (ball.off_table) ball.takeOff(std::nullopt);
    }
    balls.push_back(ball);
  }
  return balls;
}

ordered_json rackToJson(const rules::RackState& s) {
  ordered_json j;
  j["racked"] = intsToJson(s.racked);
  j["on_table"] = intsToJson(s.on_table);
  j["shooter"] = rules::playerName(s.shooter);
  j["break_next"] = s.break_next;
  j["ball_in_hand"] = s.ball_in_hand;
  j["push_out_available"] = s.push_out_available;
  j["decision"] = static_cast<int>(s.decision);
  j["winner"] = s.winner ? ordered_json(rules::playerName(*s.winner)) : ordered_json(nullptr);
  j["fouls"] = {s.fouls[0], s.fouls[1]};
  j["score"] = {s.score[0], s.score[1]};
  j["groups"] = {optionalInt(s.groups.a.has_value(), s.groups.a ? int(*s.groups.a) : 0),
                 optionalInt(s.groups.b.has_value(), s.groups.b ? int(*s.groups.b) : 0)};
  j["target"] = s.target;
  j["innings"] = {s.innings[0], s.innings[1]};
  j["inning_open"] = s.inning_open;
  j["run"] = s.run;
  j["high_run"] = {s.high_run[0], s.high_run[1]};
  j["equalising"] = s.equalising;
  j["draw"] = s.draw;
  const rules::SnookerState& k = s.snooker;
  j["snooker"] = {{"colour_on", k.colour_on},
                  {"free_ball", k.free_ball},
                  {"respotted_black", k.respotted_black},
                  {"misses", {k.misses[0], k.misses[1]}},
                  {"colour_on_before", k.colour_on_before},
                  {"free_ball_before", k.free_ball_before},
                  {"on_table_before", intsToJson(k.on_table_before)}};
  return j;
}

rules::Player player(const json& obj, const std::string& path, const char* key) {
  const std::string name = text(required(obj, path, key), member(path, key));
  if (name != "A" && name != "B") refuse(member(path, key), "expected \"A\" or \"B\"");
  return name == "A" ? rules::Player::A : rules::Player::B;
}

std::optional<rules::Group> groupAt(const json& v, const std::string& path) {
  if (v.is_null()) return std::nullopt;
  return static_cast<rules::Group>(integer(v, path, 0, 1));
}

rules::RackState parseRack(const json& v, const std::string& path,
                           const std::vector<BallState>& like) {
  expectObject(v, path);
  allowOnly(v, path,
            {"racked", "on_table", "shooter", "break_next", "ball_in_hand", "push_out_available",
             "decision", "winner", "fouls", "score", "groups", "target", "innings", "inning_open",
             "run", "high_run", "equalising", "draw", "snooker"});
  rules::RackState s;
  s.racked = ballNumbers(v, path, "racked", like);
  s.on_table = ballNumbers(v, path, "on_table", like);
  s.shooter = player(v, path, "shooter");
  s.break_next = flag(v, path, "break_next");
  s.ball_in_hand = flag(v, path, "ball_in_hand");
  s.push_out_available = flag(v, path, "push_out_available");
  s.decision = static_cast<rules::Decision>(
      integer(required(v, path, "decision"), member(path, "decision"), 0,
              static_cast<int>(rules::Decision::PlayPutBackOrReplace)));
  if (!required(v, path, "winner").is_null()) s.winner = player(v, path, "winner");
  pairOf(v, path, "fouls", s.fouls);
  pairOf(v, path, "score", s.score);
  const json& groups = required(v, path, "groups");
  const std::string gat = member(path, "groups");
  if (!groups.is_array() || groups.size() != 2) refuse(gat, "expected [A, B]");
  s.groups.a = groupAt(groups[0], element(gat, 0));
  s.groups.b = groupAt(groups[1], element(gat, 1));
  s.target = count(v, path, "target");
  pairOf(v, path, "innings", s.innings);
  s.inning_open = flag(v, path, "inning_open");
  s.run = count(v, path, "run");
  pairOf(v, path, "high_run", s.high_run);
  s.equalising = flag(v, path, "equalising");
  s.draw = flag(v, path, "draw");
  const json& k = required(v, path, "snooker");
  const std::string kat = member(path, "snooker");
  expectObject(k, kat);
  allowOnly(k, kat,
            {"colour_on", "free_ball", "respotted_black", "misses", "colour_on_before",
             "free_ball_before", "on_table_before"});
  s.snooker.colour_on = flag(k, kat, "colour_on");
  s.snooker.free_ball = flag(k, kat, "free_ball");
  s.snooker.respotted_black = flag(k, kat, "respotted_black");
  pairOf(k, kat, "misses", s.snooker.misses);
  s.snooker.colour_on_before = flag(k, kat, "colour_on_before");
  s.snooker.free_ball_before = flag(k, kat, "free_ball_before");
  s.snooker.on_table_before = ballNumbers(k, kat, "on_table_before", like);
  return s;
}

}  // namespace

ordered_json snapshotToJson(const MatchSnapshot& snapshot) {
  ordered_json j;
  j["balls"] = ballsToJson(snapshot.balls);
  j["rack"] = rackToJson(snapshot.rack);
  j["cue_pocketed"] = snapshot.cue_pocketed;
  j["balls_before"] = ballsToJson(snapshot.balls_before);
  return j;
}

MatchSnapshot parseSnapshot(const json& v, const std::vector<BallState>& like, double bound) {
  const std::string path = "state";
  expectObject(v, path);
  allowOnly(v, path, {"balls", "rack", "cue_pocketed", "balls_before"});
  MatchSnapshot s;
  s.balls = parseBallList(required(v, path, "balls"), member(path, "balls"), like, bound, true);
  s.rack = parseRack(required(v, path, "rack"), member(path, "rack"), like);
  s.cue_pocketed = flag(v, path, "cue_pocketed");
  s.balls_before = parseBallList(required(v, path, "balls_before"), member(path, "balls_before"),
                                 like, bound, false);
  return s;
}

}  // namespace nineball::io
