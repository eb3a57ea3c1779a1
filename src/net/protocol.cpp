#include "net/protocol.hpp"

#include <cmath>
#include <cstdio>

#include "io/json_fields.hpp"
#include "io/match_json.hpp"

namespace nineball::net {
namespace {

using io::Bounds;
using io::refuse;
using nlohmann::json;

// Radians agree with the degrees beside them within this (a rounding, not another shot).
constexpr double kAngleAgreement = 1e-9;
// Where a cue ball may be drawn, m from the table's centre: past any table.
constexpr double kMostPlace = 5.0;

std::string textField(const json& j, const char* key, std::size_t most = kMostText) {
  const std::string s = io::text(io::required(j, "", key), key);
  if (s.size() > most) refuse(key, "longer than " + std::to_string(most) + " bytes");
  return s;
}

std::string tokenField(const json& j, const char* key) {
  const std::string s = textField(j, key, kSeatTokenChars);
  if (!s.empty() && !isSeatToken(s)) {
    refuse(key, "expected " + std::to_string(kSeatTokenChars) + " hexadecimal digits or \"\"");
  }
  return s;
}

std::size_t indexField(const json& j) {
  return static_cast<std::size_t>(
      io::integer(io::required(j, "", "index"), "index", 0, static_cast<int>(kMostTurns)));
}

std::uint64_t parseHash(const json& v, const std::string& path) {
  const std::string s = io::text(v, path);
  if (s.size() != 16 || s.find_first_not_of("0123456789abcdef") != std::string::npos) {
    refuse(path, "expected 16 hexadecimal digits");
  }
  return std::stoull(s, nullptr, 16);
}

Vec2 pair(const json& v, const std::string& path, Bounds bounds) {
  if (!v.is_array() || v.size() != 2) refuse(path, "expected [x, y], found " + io::describe(v));
  return {io::number(v[0], io::element(path, 0), bounds),
          io::number(v[1], io::element(path, 1), bounds)};
}

Seat seatField(const json& v, const std::string& path) {
  const std::string name = io::text(io::required(v, path, "player"), io::member(path, "player"));
  const auto seat = seatFromName(name);
  if (!seat) refuse(io::member(path, "player"), "expected " + seatNamesText());
  return *seat;
}

WireTurn parseTurnEntry(const json& v, const std::string& path) {
  io::expectObject(v, path);
  io::allowOnly(v, path, {"turn", "player"});
  const json& turn = io::required(v, path, "turn");
  io::expectObject(turn, io::member(path, "turn"));
  WireTurn w;
  w.turn = turn;
  w.player = seatField(v, path);
  return w;
}

json turnEntry(const WireTurn& w) {
  return {{"turn", w.turn}, {"player", seatName(w.player)}};
}

Race parseRace(const json& v) {
  io::expectObject(v, "race");
  io::allowOnly(v, "race", {"best_of", "rack", "racks_won"});
  Race r;
  r.best_of = io::integer(io::required(v, "race", "best_of"), "race.best_of", 1, 99);
  r.rack = io::integer(io::required(v, "race", "rack"), "race.rack", 0, 200);
  const json& won = io::required(v, "race", "racks_won");
  if (!won.is_array() || won.size() != 2) refuse("race.racks_won", "expected [A, B]");
  r.racks_won = {io::integer(won[0], "race.racks_won[0]", 0, 99),
                 io::integer(won[1], "race.racks_won[1]", 0, 99)};
  return r;
}

Message parse(const json& j) {
  const std::string type = io::text(io::required(j, "", "type"), "type");
  if (type == "hello") {
    io::allowOnly(j, "", {"type", "protocol", "build", "name", "code", "token", "player"});
    Hello h;
    h.protocol = io::integer(io::required(j, "", "protocol"), "protocol", 0, 1 << 20);
    h.build = textField(j, "build");
    h.name = cleanName(textField(j, "name"));
    h.code = textField(j, "code", kMostCodeChars);
    h.token = tokenField(j, "token");
    h.player = seatField(j, "");
    return h;
  }
  if (type == "welcome") {
    io::allowOnly(
        j, "", {"type", "protocol", "build", "name", "match", "race", "turns", "hashes", "token"});
    Welcome w;
    w.protocol = io::integer(io::required(j, "", "protocol"), "protocol", 0, 1 << 20);
    w.build = textField(j, "build");
    w.name = cleanName(textField(j, "name"));
    w.match = io::required(j, "", "match");
    io::expectObject(w.match, "match");
    w.race = parseRace(io::required(j, "", "race"));
    const json& turns = io::required(j, "", "turns");
    const json& hashes = io::required(j, "", "hashes");
    if (!turns.is_array() || turns.size() > kMostTurns)
      refuse("turns", "expected the rack's turns");
    if (!hashes.is_array() || hashes.size() != turns.size()) {
      refuse("hashes", "expected one hash per turn");
    }
    for (std::size_t i = 0; i < turns.size(); ++i) {
      w.turns.push_back(parseTurnEntry(turns[i], io::element("turns", i)));
      w.hashes.push_back(parseHash(hashes[i], io::element("hashes", i)));
    }
    w.token = tokenField(j, "token");
    if (w.token.empty()) refuse("token", "expected the joiner's seat token");
    return w;
  }
  if (type == "refuse") {
    io::allowOnly(j, "", {"type", "reason"});
    return Refuse{cleanText(textField(j, "reason"))};
  }
  if (type == "bye") {
    io::allowOnly(j, "", {"type", "reason", "finished"});
    const json& finished = io::required(j, "", "finished");
    if (!finished.is_boolean()) refuse("finished", "expected true or false");
    return Bye{cleanText(textField(j, "reason")), finished.get<bool>()};
  }
  if (type == "turn") {
    io::allowOnly(j, "", {"type", "index", "turn", "player"});
    TurnMessage m;
    m.index = indexField(j);
    json entry = {{"turn", io::required(j, "", "turn")}, {"player", io::required(j, "", "player")}};
    m.turn = parseTurnEntry(entry, "");
    return m;
  }
  if (type == "hash") {
    io::allowOnly(j, "", {"type", "index", "hash"});
    return HashMessage{indexField(j), parseHash(io::required(j, "", "hash"), "hash")};
  }
  if (type == "state") {
    io::allowOnly(j, "", {"type", "index", "state"});
    StateMessage m;
    m.index = indexField(j);
    m.state = io::required(j, "", "state");
    io::expectObject(m.state, "state");
    return m;
  }
  if (type == "aim") {
    io::allowOnly(j, "", {"type", "heading_rad", "speed", "tip", "elevation_rad", "cue"});
    Aim a;
    a.heading_rad = io::number(io::required(j, "", "heading_rad"), "heading_rad",
                               Bounds::closed(-2.0 * kPi, 2.0 * kPi));
    a.speed = io::number(io::required(j, "", "speed"), "speed", Bounds::nonNegative(20.0));
    a.tip = pair(io::required(j, "", "tip"), "tip", Bounds::closed(-1.0, 1.0));
    a.elevation_rad = io::number(io::required(j, "", "elevation_rad"), "elevation_rad",
                                 Bounds::closed(0.0, kPi / 2.0));
    const json& cue = io::required(j, "", "cue");
    if (!cue.is_null()) a.cue = pair(cue, "cue", Bounds::closed(-kMostPlace, kMostPlace));
    return a;
  }
  if (type == "rematch") {
    io::allowOnly(j, "", {"type"});
    return Rematch{};
  }
  refuse("type", "unknown message type " + io::quote(type));
}

struct ToJson {
  json operator()(const Hello& m) const {
    return {{"type", "hello"},
            {"protocol", m.protocol},
            {"build", m.build},
            {"name", m.name},
            {"code", m.code},
            {"token", m.token},
            {"player", seatName(m.player)}};
  }
  json operator()(const Welcome& m) const {
    json turns = json::array();
    json hashes = json::array();
    for (const WireTurn& t : m.turns) turns.push_back(turnEntry(t));
    for (std::uint64_t h : m.hashes) hashes.push_back(hashText(h));
    return {{"type", "welcome"},
            {"protocol", m.protocol},
            {"build", m.build},
            {"name", m.name},
            {"match", m.match},
            {"race",
             {{"best_of", m.race.best_of},
              {"rack", m.race.rack},
              {"racks_won", {m.race.racks_won[0], m.race.racks_won[1]}}}},
            {"turns", turns},
            {"hashes", hashes},
            {"token", m.token}};
  }
  // A reason is cut to what the other side reads (kMostText), so a long one still arrives.
  json operator()(const Refuse& m) const {
    return {{"type", "refuse"}, {"reason", cleanText(m.reason)}};
  }
  json operator()(const TurnMessage& m) const {
    return {{"type", "turn"},
            {"index", m.index},
            {"turn", m.turn.turn},
            {"player", seatName(m.turn.player)}};
  }
  json operator()(const HashMessage& m) const {
    return {{"type", "hash"}, {"index", m.index}, {"hash", hashText(m.hash)}};
  }
  json operator()(const StateMessage& m) const {
    return {{"type", "state"}, {"index", m.index}, {"state", m.state}};
  }
  json operator()(const Aim& m) const {
    return {{"type", "aim"},
            {"heading_rad", m.heading_rad},
            {"speed", m.speed},
            {"tip", {m.tip.x, m.tip.y}},
            {"elevation_rad", m.elevation_rad},
            {"cue", m.cue ? json{m.cue->x, m.cue->y} : json(nullptr)}};
  }
  json operator()(const Rematch&) const { return {{"type", "rematch"}}; }
  json operator()(const Bye& m) const {
    return {{"type", "bye"}, {"reason", cleanText(m.reason)}, {"finished", m.finished}};
  }
};

}  // namespace

json toJson(const Message& message) {
  return std::visit(ToJson{}, message);
}

std::optional<Message> readMessage(const json& j, std::string& why) {
  try {
    if (!j.is_object()) refuse("message", "expected an object, found " + io::describe(j));
    return parse(j);
  } catch (const io::ParseError& e) {
    why = e.message;
    return std::nullopt;
  }
}

WireTurn wireTurn(const TurnInput& turn, const Seat& player, rules::Game game) {
  WireTurn w;
  w.player = player;
  w.turn = io::turnToJson(turn, game);
  if (turn.kind != TurnInput::Kind::Decision) {
    w.turn["heading_rad"] = turn.shot.heading_rad;
    w.turn["elevation_rad"] = turn.shot.elevation_rad;
  }
  return w;
}

std::optional<TurnInput> parseWireTurn(const WireTurn& wire, const MatchSetup& setup,
                                       std::string& why) {
  try {
    json script_turn = wire.turn;
    std::optional<double> heading;
    std::optional<double> elevation;
    for (const char* key : {"heading_rad", "elevation_rad"}) {
      if (!script_turn.contains(key)) continue;
      const double v = io::number(script_turn[key], io::member("turn", key),
                                  Bounds::closed(-2.0 * kPi, 2.0 * kPi));
      (std::string(key) == "heading_rad" ? heading : elevation) = v;
      script_turn.erase(key);
    }
    TurnInput turn = io::parseTurn(script_turn, "turn", setup.physics.ball_mass, setup.game);
    if (turn.kind == TurnInput::Kind::Decision) {
      if (heading || elevation) refuse("turn", "a decision carries no angles");
      return turn;
    }
    if (!heading || !elevation) refuse("turn", "needs \"heading_rad\" and \"elevation_rad\"");
    if (std::abs(std::remainder(*heading - turn.shot.heading_rad, 2.0 * kPi)) > kAngleAgreement ||
        std::abs(*elevation - turn.shot.elevation_rad) > kAngleAgreement) {
      refuse("turn", "the radians and the degrees give different shots");
    }
    turn.shot.heading_rad = *heading;
    turn.shot.elevation_rad = *elevation;
    return turn;
  } catch (const io::ParseError& e) {
    why = e.message;
    return std::nullopt;
  }
}

std::string hashText(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

namespace {

// The length of the well-formed UTF-8 character at `at` (RFC 3629: no overlong forms, no
// surrogates, nothing past U+10FFFF), or 0 when the bytes there are not one.
std::size_t utf8Length(const std::string& s, std::size_t at) {
  const auto u = static_cast<unsigned char>(s[at]);
  const std::size_t n = u < 0x80           ? 1
                        : (u >> 5) == 0x6  ? 2
                        : (u >> 4) == 0xe  ? 3
                        : (u >> 3) == 0x1e ? 4
                                           : 0;
  if (n <= 1 || at + n > s.size()) return n == 1 ? 1 : 0;
  std::uint32_t code = u & (0x7f >> n);
  for (std::size_t i = 1; i < n; ++i) {
    const auto c = static_cast<unsigned char>(s[at + i]);
    if ((c >> 6) != 0x2) return 0;
    code = (code << 6) | (c & 0x3f);
  }
  static const std::uint32_t kLeast[5] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < kLeast[n] || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return 0;
  return n;
}

// C0 and C1 control characters, and DEL.
bool isControl(const std::string& s, std::size_t at, std::size_t n) {
  const auto u = static_cast<unsigned char>(s[at]);
  if (n == 1) return u < 0x20 || u == 0x7f;
  return n == 2 && u == 0xc2 && static_cast<unsigned char>(s[at + 1]) < 0xa0;
}

// `text` without control characters and bytes that are not UTF-8, whole characters only (a
// cut never leaves half of one), at most `most_chars` characters and `most_bytes` bytes.
std::string printable(const std::string& text, std::size_t most_chars, std::size_t most_bytes) {
  std::string out;
  std::size_t chars = 0;
  for (std::size_t i = 0; i < text.size() && chars < most_chars;) {
    const std::size_t n = utf8Length(text, i);
    if (n == 0) {
      ++i;
      continue;
    }
    if (!isControl(text, i, n)) {
      if (out.size() + n > most_bytes) break;
      out.append(text, i, n);
      ++chars;
    }
    i += n;
  }
  return out;
}

}  // namespace

std::string cleanName(const std::string& name) {
  // Bytes that are not UTF-8 are dropped as control characters are (a peer's JSON cannot
  // carry them, but a local name from the command line can).
  const std::string out = printable(name, kMostNameChars, std::string::npos);
  return out.empty() ? "Player" : out;
}

std::string cleanText(const std::string& text, std::size_t most_bytes) {
  return printable(text, std::string::npos, most_bytes);
}

bool isSeatToken(const std::string& text) {
  return text.size() == kSeatTokenChars &&
         text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

}  // namespace nineball::net
