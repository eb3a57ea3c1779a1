// What the protocol fuzz sends a live host: byte strings a peer must never get away with, each
// drawn from a seeded generator. Every one must be refused (a refuse message, or the link
// closed); none may be something the host could take as a move of the rack.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "net/protocol.hpp"
#include "net/wire.hpp"

namespace nineball::net_test {

using Rng = std::mt19937_64;
using nlohmann::json;

/// One hostile burst: its bytes, how many messages (frames or raw pieces) it holds, and what
/// the host's answer should look like.
struct Hostile {
  std::string kind;
  std::string bytes;
  int messages = 1;
  /// Whole frames: the peer keeps pinging while it waits, so only a refusal ends the link.
  /// Off for broken streams and silent peers, which the host may close on silence.
  bool keep_alive = true;
  /// The refuse message must say this (refused by name).
  std::string reason_has;
  /// The host must send its state whole before refusing (a wrong hash is healed first).
  bool expect_state = false;
};

inline int uniform(Rng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

inline std::string randomBytes(Rng& rng, std::size_t n) {
  std::string s(n, '\0');
  for (char& c : s) c = static_cast<char>(uniform(rng, 0, 255));
  return s;
}

inline std::string lengthPrefix(std::uint32_t n) {
  return {static_cast<char>(n >> 24), static_cast<char>((n >> 16) & 0xff),
          static_cast<char>((n >> 8) & 0xff), static_cast<char>(n & 0xff)};
}

inline std::string framedText(const std::string& text) {
  return net::framed(text);
}

/// The join code the tests' hosts are given.
constexpr char kCode[] = "7KQ4-ZP2M";

/// A hello the tests' hosts take: this build, the code, and the seat's token when it is taken.
inline json goodHello(const std::string& name = "Fuzz", const std::string& token = "") {
  return {{"type", "hello"},         {"protocol", net::kProtocolVersion},
          {"build", net::buildId()}, {"name", name},
          {"code", kCode},           {"token", token},
          {"player", "human"}};
}

/// A turn that reads as a turn of nine-ball (heading, speed, tip, elevation and the exact
/// radians beside them).
inline json plausibleTurn(Rng& rng) {
  TurnInput t;
  t.shot.heading_rad = std::uniform_real_distribution<double>(-3.0, 3.0)(rng);
  t.shot.speed = std::uniform_real_distribution<double>(0.5, 8.0)(rng);
  t.shot.tip = {0.1, -0.2};
  t.shot.elevation_rad = 0.1;
  return net::wireTurn(t, HumanSeat{}, rules::Game::NineBall).turn;
}

/// A turn message no state of a rack could take: one field out of range, of the wrong type,
/// unknown, or the radians disagreeing with the degrees.
inline json brokenTurnMessage(Rng& rng, std::size_t index) {
  json turn = plausibleTurn(rng);
  json message = {{"type", "turn"}, {"index", index}, {"turn", turn}, {"player", "human"}};
  switch (uniform(rng, 0, 17)) {
    case 0:
      turn["speed"] = std::uniform_real_distribution<double>(14.01, 1e6)(rng);
      break;
    case 1:
      turn["speed"] = -1.0;
      break;
    case 2:
      turn["tip"] = {uniform(rng, 2, 100), 0};
      break;
    case 3:
      turn["tip"] = "centre";
      break;
    case 4:
      turn["elevation_deg"] = 90.5;
      break;
    case 5:
      turn["call"] = {{"ball", uniform(rng, 16, 1000)}, {"pocket", "top-left"}};
      break;
    case 6:
      turn["call"] = {{"ball", 0}, {"pocket", "corner"}};
      break;
    case 7:
      turn["call"] = {{"ball", 9}, {"pocket", "middle"}};
      break;
    case 8:
      turn["heading_rad"] = turn["heading_rad"].get<double>() + 0.25;
      break;
    case 9:
      turn.erase("heading_rad");
      break;
    case 10:
      turn["heading_rad"] = 1e308;
      break;
    case 11:
      turn["cue"] = {"x", 0};
      break;
    case 12:
      turn["spin"] = 3;
      break;
    case 13:
      message["player"] = "ai:godlike";
      break;
    case 14:
      message["index"] = -1;
      break;
    case 15:
      turn = json::array();
      break;
    case 16:
      // Off any table: not in hand, or no place for it.
      turn["cue"] = {uniform(rng, 3, 1000), -0.1};
      message["turn"] = turn;
      return message;
    default:
      turn["decision"] = "maybe";
      break;
  }
  message["turn"] = turn;
  return message;
}

/// Messages that may only come first, or never, from a joiner; sent first they are refused
/// as "not a hello" (and the rest by their shape).
inline json notAHello(Rng& rng) {
  switch (uniform(rng, 0, 8)) {
    case 0:
      return brokenTurnMessage(rng, 0);
    case 1:
      return {{"type", "turn"}, {"index", 0}, {"turn", plausibleTurn(rng)}, {"player", "human"}};
    case 2:
      return {{"type", "hash"}, {"index", 0}, {"hash", "0123456789abcdef"}};
    case 3:
      return {{"type", "state"}, {"index", 0}, {"state", json::object()}};
    case 4:
      return {{"type", "aim"}, {"heading_rad", 0.5},   {"speed", 1.0},
              {"tip", {0, 0}}, {"elevation_rad", 0.0}, {"cue", nullptr}};
    case 5:
      return {{"type", "rematch"}};
    case 6:
      return {{"type", "bye"}, {"reason", "bye"}, {"finished", false}};
    case 7:
      return {{"type", "refuse"}, {"reason", "no"}};
    default:
      return {{"type", "welcome"},       {"protocol", 1},
              {"build", net::buildId()}, {"name", "x"},
              {"match", json::object()}, {"race", json::object()},
              {"turns", json::array()},  {"hashes", json::array()}};
  }
}

/// JSON text that is not a message: not JSON, nested too deep, not an object, without a
/// type, of an unknown type, with a key twice, not UTF-8, with a NUL, a number too large.
inline std::string notAMessage(Rng& rng) {
  switch (uniform(rng, 0, 12)) {
    case 0: {
      static const std::vector<std::string> bad = {"{",
                                                   "}",
                                                   "nul",
                                                   "[1,2",
                                                   "\"abc",
                                                   "{\"type\":}",
                                                   "{'type':'hello'}",
                                                   "0x10",
                                                   "{\"type\":\"hello\"}}",
                                                   "tru",
                                                   ",",
                                                   "-"};
      return bad[uniform(rng, 0, static_cast<int>(bad.size()) - 1)];
    }
    case 1: {
      const int depth = uniform(rng, 17, 200000);
      return "{\"type\":\"hello\",\"x\":" + std::string(depth, '[') + std::string(depth, ']') + "}";
    }
    case 2:
      return std::string(uniform(rng, 17, 50000), '[');
    case 3: {
      static const std::vector<std::string> scalars = {
          "[]", "[{\"type\":\"hello\"}]", "3", "-0.5", "\"hello\"", "null", "true", "false"};
      return scalars[uniform(rng, 0, static_cast<int>(scalars.size()) - 1)];
    }
    case 4:
      return R"({"kind":"hello","protocol":1})";
    case 5:
      return R"({"type":1})";
    case 6:
      return "{\"type\":\"" + std::string(uniform(rng, 1, 30), 'z') + "\"}";
    case 7:
      return R"({"type":"hello","type":"hello","protocol":1,"build":"b","name":"n"})";
    case 8:
      return std::string("{\"type\":\"hello\",\"name\":\"\xff\xfe\"}");
    case 9:
      return std::string("{\"type\":\"hello\"}\0{}", 18);
    case 10:
      return R"({"type":"hello","protocol":1e400,"build":"b","name":"n"})";
    case 11:
      return R"({"type":"ping","x":)" + std::to_string(uniform(rng, 0, 9)) + "}" + " trailing";
    default:
      return randomBytes(rng, uniform(rng, 1, 300));
  }
}

/// A join code of the host's alphabet that is not the tests' (a guess).
inline std::string randomCode(Rng& rng) {
  static const char kAlphabet[] = "23456789ABCDEFGHJKMNPQRSTUVWXYZ";
  std::string code;
  do {
    code.clear();
    for (int i = 0; i < 8; ++i) code += kAlphabet[uniform(rng, 0, 30)];
  } while (code == "7KQ4ZP2M");
  return code;
}

/// A hello the host refuses: another protocol or build (by name), no or a wrong join code, or a
/// field out of shape.
inline Hostile badHello(Rng& rng) {
  json h = goodHello();
  Hostile out;
  switch (uniform(rng, 0, 12)) {
    case 8:
      h["code"] = uniform(rng, 0, 1) ? std::string() : randomCode(rng);
      out.kind = "hello without the join code";
      out.reason_has = "join code";
      break;
    case 9:
      h["code"] = std::string(uniform(rng, 33, 300), 'C');
      out.kind = "hello, join code too long";
      out.reason_has = "code";
      break;
    case 10:
      h["token"] =
          uniform(rng, 0, 1) ? std::string(32, 'Z') : std::string(uniform(rng, 1, 31), 'a');
      out.kind = "hello, a seat token out of shape";
      out.reason_has = "token";
      break;
    case 11:
      h["player"] = uniform(rng, 0, 1) ? json("ai:god") : json(7);
      out.kind = "hello, a player that is none";
      out.reason_has = "player";
      break;
    case 0:
      h["protocol"] = net::kProtocolVersion + uniform(rng, 1, 1000);
      out.kind = "hello of another protocol";
      out.reason_has = "protocol";
      break;
    case 1:
      h["protocol"] = 0;
      out.kind = "hello of another protocol";
      out.reason_has = "protocol";
      break;
    case 2:
      h["build"] = "nineball 0.0.1 (deadbeef, GNU 1, Release)";
      out.kind = "hello of another build";
      out.reason_has = "same build";
      break;
    case 3:
      h["build"] = net::buildId() + " ";
      out.kind = "hello of another build";
      out.reason_has = "same build";
      break;
    case 4:
      h["name"] = std::string(uniform(rng, 201, 250000), 'n');
      out.kind = "hello, name too long";
      break;
    case 5:
      h.erase("build");
      out.kind = "hello without a build";
      break;
    case 6:
      h["protocol"] = "1";
      out.kind = "hello, protocol a string";
      break;
    default:
      h["cheat"] = true;
      out.kind = "hello with an extra key";
      break;
  }
  out.bytes = net::framed(h.dump());
  return out;
}

/// Broken streams: random bytes, lengths of 0 or past the bound, a length past the bound
/// after a good frame.
inline Hostile brokenStream(Rng& rng) {
  Hostile out;
  out.keep_alive = false;
  switch (uniform(rng, 0, 4)) {
    case 0:
      out.kind = "random bytes";
      out.bytes = randomBytes(rng, uniform(rng, 4, 4000));
      // Random bytes may begin with a plausible length and wait for the rest: make it
      // implausible, so the answer is prompt (truncated frames have their own kind).
      out.bytes[0] = static_cast<char>(uniform(rng, 1, 255));
      break;
    case 1:
      out.kind = "length past the bound";
      out.bytes = lengthPrefix(static_cast<std::uint32_t>(
                      uniform(rng, static_cast<int>(net::kMaxMessageBytes) + 1, 0x7fffffff))) +
                  randomBytes(rng, uniform(rng, 0, 64));
      break;
    case 2:
      out.kind = "zero length";
      out.bytes = lengthPrefix(0) + randomBytes(rng, uniform(rng, 0, 16));
      break;
    case 3:
      out.kind = "length 0xffffffff";
      out.bytes = lengthPrefix(0xffffffffu);
      break;
    default:
      out.kind = "bad length behind a message";
      out.bytes =
          framedText(R"({"type":"ping"})") + lengthPrefix(uniform(rng, 0, 1) ? 0u : 0x01000000u);
      out.messages = 2;
      break;
  }
  return out;
}

/// A flood: more messages in a second than the link allows.
inline Hostile flood(Rng& rng, int per_second, const json& message) {
  Hostile out;
  out.kind = "flood";
  out.messages = per_second + uniform(rng, 5, 200);
  const std::string one = net::framed(message.dump());
  for (int i = 0; i < out.messages; ++i) out.bytes += one;
  return out;
}

}  // namespace nineball::net_test
