// The protocol's messages: each reads back as it was sent, and anything a peer could send
// that is not one of them is refused by name before it is believed.
#include "net/protocol.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "net/connection.hpp"
#include "net/handshake.hpp"
#include "nineball/match.hpp"

namespace nineball::net {
namespace {

using nlohmann::json;

// The message read back from its JSON; a test failure (and an empty Refuse) when refused.
Message readBack(const json& j) {
  std::string why;
  const auto m = readMessage(j, why);
  if (!m) {
    ADD_FAILURE() << "refused " << j.dump() << ": " << why;
    return Refuse{};
  }
  return *m;
}

// Why `j` is refused; "" (and a test failure) when it is read.
std::string refusal(const json& j) {
  std::string why;
  if (readMessage(j, why)) {
    ADD_FAILURE() << "read " << j.dump();
    return "";
  }
  EXPECT_FALSE(why.empty()) << j.dump();
  return why;
}

bool mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TurnInput aSpunShot(double heading_rad, double speed) {
  TurnInput t;
  t.shot.heading_rad = heading_rad;
  t.shot.speed = speed;
  t.shot.tip = {0.25, -0.125};
  t.shot.elevation_rad = 0.0872664625997164788;  // about 5 degrees, not a round number of them
  return t;
}

// One of every message, with its fields away from their defaults.
std::vector<Message> oneOfEach() {
  const MatchSetup setup;
  TurnInput placed = aSpunShot(0.3, 2.5);
  placed.cue = Vec2{-0.6, 0.1};
  Welcome w;
  w.protocol = kProtocolVersion;
  w.build = buildId();
  w.name = "Host";
  w.match = {{"game", "nine-ball"}, {"seed", 7}};
  w.race = Race{3, 1, {1, 0}};
  w.turns = {wireTurn(aSpunShot(1.0, 6.0), HumanSeat{}, setup.game),
             wireTurn(placed, ComputerSeat{ai::Level::Beginner}, setup.game)};
  w.hashes = {0x0123456789abcdefull, 0xfedcba9876543210ull};
  w.token = "0123456789abcdef0123456789abcdef";
  TurnInput decision;
  decision.kind = TurnInput::Kind::Decision;
  decision.shoot = false;
  Aim placing{1.25, 3.0, {0.5, -0.5}, 0.2, Vec2{-0.5, 0.25}};
  Aim plain{-2.0, 0.0, {0.0, 0.0}, 0.0, std::nullopt};
  return {helloFrom("Ann"),
          helloFrom("Bo", "7KQ4-ZP2M", std::string(32, 'e'), ComputerSeat{ai::Level::Master}),
          w,
          Refuse{"another build"},
          TurnMessage{4, wireTurn(aSpunShot(-2.5, 1.5), HumanSeat{}, setup.game)},
          TurnMessage{5, wireTurn(decision, HumanSeat{}, setup.game)},
          HashMessage{4, 0xffffffffffffffffull},
          HashMessage{0, 0},
          StateMessage{2, json{{"balls", json::array()}}},
          placing,
          plain,
          Rematch{},
          Bye{"the rack is played", true},
          Bye{"quit", false}};
}

TEST(Protocol, EveryMessageReadsBackAsItWasSent) {
  for (const Message& m : oneOfEach()) {
    const json sent = toJson(m);
    const Message back = readBack(sent);
    EXPECT_EQ(back.index(), m.index()) << sent.dump();
    EXPECT_EQ(toJson(back), sent);
    // And through the wire's text, as a peer receives it.
    std::string why;
    const auto parsed = parseMessage(sent.dump(), why);
    ASSERT_TRUE(parsed.has_value()) << why;
    EXPECT_EQ(toJson(readBack(*parsed)), sent);
  }
}

TEST(Protocol, HashesAndAnglesKeepEveryBit) {
  const HashMessage h{9, 0x8000000000000001ull};
  const auto back = std::get<HashMessage>(readBack(toJson(h)));
  EXPECT_EQ(back.hash, h.hash);
  EXPECT_EQ(hashText(0x00000000000000abull), "00000000000000ab");

  const Aim a{std::nextafter(1.0, 2.0), 0.1, {1.0 / 3.0, -1.0 / 7.0}, 0.3, std::nullopt};
  const auto aim = std::get<Aim>(readBack(json::parse(toJson(a).dump())));
  EXPECT_EQ(std::memcmp(&aim.heading_rad, &a.heading_rad, sizeof(double)), 0);
  EXPECT_EQ(aim.tip.x, a.tip.x);
  EXPECT_EQ(aim.tip.y, a.tip.y);
}

TEST(Protocol, AnythingButAnObjectWithAKnownTypeIsRefused) {
  EXPECT_TRUE(mentions(refusal(json::array()), "expected an object"));
  EXPECT_TRUE(mentions(refusal(json("hello")), "expected an object"));
  EXPECT_TRUE(mentions(refusal(json(nullptr)), "expected an object"));
  EXPECT_TRUE(mentions(refusal(json::object()), "type"));
  EXPECT_TRUE(mentions(refusal({{"type", 3}}), "type"));
  EXPECT_TRUE(mentions(refusal({{"type", "ping"}}), "unknown message type \"ping\""));
  EXPECT_TRUE(mentions(refusal({{"type", "HELLO"}}), "unknown message type"));
  EXPECT_TRUE(mentions(refusal({{"type", "turn!"}}), "unknown message type"));
}

TEST(Protocol, AMissingOrExtraKeyIsRefusedByName) {
  for (const Message& m : oneOfEach()) {
    const json sent = toJson(m);
    json extra = sent;
    extra["cheat"] = true;
    EXPECT_TRUE(mentions(refusal(extra), "cheat")) << sent.dump();
    for (const auto& [key, value] : sent.items()) {
      if (key == "type") continue;
      json missing = sent;
      missing.erase(key);
      EXPECT_TRUE(mentions(refusal(missing), key)) << key << " of " << sent.dump();
    }
  }
}

TEST(Protocol, AValueOfTheWrongTypeIsRefusedByName) {
  const json hello = toJson(helloFrom("n"));
  for (const char* key : {"protocol", "build", "name"}) {
    for (const json& wrong : {json(nullptr), json::array(), json::object(), json(true)}) {
      json j = hello;
      j[key] = wrong;
      EXPECT_TRUE(mentions(refusal(j), key)) << j.dump();
    }
  }
  EXPECT_TRUE(mentions(
      refusal({{"type", "hello"}, {"protocol", 1.5}, {"build", "b"}, {"name", "n"}}), "protocol"));
  EXPECT_TRUE(
      mentions(refusal({{"type", "hash"}, {"index", "3"}, {"hash", "0000000000000000"}}), "index"));
  EXPECT_TRUE(
      mentions(refusal({{"type", "hash"}, {"index", -1}, {"hash", "0000000000000000"}}), "index"));
  EXPECT_TRUE(
      mentions(refusal({{"type", "hash"}, {"index", 501}, {"hash", "0000000000000000"}}), "index"));
  EXPECT_TRUE(mentions(refusal({{"type", "bye"}, {"reason", "x"}, {"finished", 1}}), "finished"));
  EXPECT_TRUE(
      mentions(refusal({{"type", "state"}, {"index", 0}, {"state", json::array()}}), "state"));
  EXPECT_TRUE(mentions(refusal({{"type", "turn"}, {"index", 0}, {"turn", 3}, {"player", "human"}}),
                       "turn"));
  EXPECT_TRUE(mentions(
      refusal({{"type", "turn"}, {"index", 0}, {"turn", json::object()}, {"player", "robot"}}),
      "player"));
  EXPECT_TRUE(mentions(refusal({{"type", "refuse"}, {"reason", std::string(201, 'r')}}), "reason"));
}

TEST(Protocol, AHashMustBeSixteenLowercaseHexDigits) {
  for (const json& bad :
       {json("0123456789abcde"), json("0123456789abcdef0"), json("0123456789ABCDEF"),
        json("0123456789abcdeg"), json(" 123456789abcdef"), json("-123456789abcdef"),
        json("0x23456789abcdef"), json(1234), json("")}) {
    EXPECT_TRUE(mentions(refusal({{"type", "hash"}, {"index", 0}, {"hash", bad}}), "hash"))
        << bad.dump();
  }
}

TEST(Protocol, AnAimOutOfRangeIsRefusedByField) {
  const json good = toJson(Aim{0.5, 2.0, {0.1, 0.1}, 0.1, Vec2{0.0, 0.0}});
  const std::vector<std::pair<const char*, json>> bad = {
      {"heading_rad", 7.0},   {"heading_rad", -6.3},    {"speed", -0.1},
      {"speed", 20.5},        {"tip", {1.5, 0.0}},      {"tip", {0.0, -1.01}},
      {"tip", {0.0}},         {"tip", {0.0, 0.0, 0.0}}, {"elevation_rad", -0.01},
      {"elevation_rad", 1.6}, {"cue", {6.0, 0.0}},      {"cue", {0.0, -5.5}},
      {"cue", "here"},        {"speed", "fast"},
  };
  for (const auto& [key, value] : bad) {
    json j = good;
    j[key] = value;
    EXPECT_TRUE(mentions(refusal(j), key)) << j.dump();
  }
}

TEST(Protocol, ARaceOutOfRangeInAWelcomeIsRefused) {
  json w = toJson(std::get<Welcome>(oneOfEach()[2]));
  for (const auto& [key, value] : std::vector<std::pair<const char*, json>>{
           {"best_of", 0}, {"best_of", 100}, {"rack", -1}, {"racks_won", {1}}}) {
    json j = w;
    j["race"][key] = value;
    EXPECT_TRUE(mentions(refusal(j), "race")) << j.dump();
  }
  json fewer_hashes = w;
  fewer_hashes["hashes"].erase(0);
  EXPECT_TRUE(mentions(refusal(fewer_hashes), "hashes"));
  json bad_player = w;
  bad_player["turns"][1]["player"] = "ai:godlike";
  EXPECT_TRUE(mentions(refusal(bad_player), "turns[1].player"));
}

TEST(Protocol, NamesAreCleanedOfControlCharactersAndCutToWholeCharacters) {
  EXPECT_EQ(cleanName("Ann"), "Ann");
  EXPECT_EQ(cleanName(""), "Player");
  EXPECT_EQ(cleanName("\x01\x1b\x7f"), "Player");
  EXPECT_EQ(cleanName("A\tn\nn\x1b[31m"), "Ann[31m");
  EXPECT_EQ(cleanName(std::string(40, 'x')), std::string(kMostNameChars, 'x'));
  // 30 characters of two bytes each: cut to 24 characters, 48 bytes, never half of one.
  std::string accents;
  for (int i = 0; i < 30; ++i) accents += "\xc3\xa9";  // é
  EXPECT_EQ(cleanName(accents).size(), 2 * kMostNameChars);
  // Three- and four-byte characters count as one each.
  std::string wide = "\xe2\x82\xac\xf0\x9f\x8e\xb1";  // € and the billiards ball
  EXPECT_EQ(cleanName(wide), wide);
  std::string mixed;
  for (int i = 0; i < 23; ++i) mixed += "a";
  mixed += "\xf0\x9f\x8e\xb1\xf0\x9f\x8e\xb1";
  EXPECT_EQ(cleanName(mixed), std::string(23, 'a') + "\xf0\x9f\x8e\xb1");
  // A sequence cut short at the end is dropped, not sent as half a character.
  EXPECT_EQ(cleanName("Bo\xe2\x82"), "Bo");
  // A name read from a hello is cleaned the same way.
  const auto hello = std::get<Hello>(readBack({{"type", "hello"},
                                               {"protocol", 1},
                                               {"build", "b"},
                                               {"name", "\x1b[2JEve" + std::string(30, '!')},
                                               {"code", "C"},
                                               {"token", ""},
                                               {"player", "human"}}));
  EXPECT_EQ(hello.name, "[2JEve" + std::string(kMostNameChars - 6, '!'));
}

TEST(Protocol, ANameNeverCarriesBytesThatAreNotUtf8) {
  // A lead byte without its continuation bytes, a stray continuation byte, an overlong form, a
  // surrogate and a C1 control character are dropped; the rest of the name stays.
  const std::vector<std::pair<std::string, std::string>> cases = {{"Al\xc3x", "Alx"},
                                                                  {"Al\xe2\x82x", "Alx"},
                                                                  {"Al\xf0\x9f\x8ex", "Alx"},
                                                                  {"Al\x80", "Al"},
                                                                  {"Ren\xe9"
                                                                   "e",
                                                                   "Rene"},
                                                                  {"A\xc0\xafl", "Al"},
                                                                  {"A\xed\xa0\x80l", "Al"},
                                                                  {"A\xc2\x85l", "Al"},
                                                                  {"A\xf4\x90\x80\x80l", "Al"},
                                                                  {"\xff\xfe", "Player"},
                                                                  {"\xc2\xa0"
                                                                   "Al",
                                                                   "\xc2\xa0"
                                                                   "Al"}};
  for (const auto& [bad, clean] : cases) {
    EXPECT_EQ(cleanName(bad), clean) << json(clean).dump();
    std::string dumped;
    EXPECT_NO_THROW(dumped = json(cleanName(bad)).dump()) << clean;
  }
}

// --- the turn on the wire ---

TEST(Protocol, AWireTurnKeepsTheRadiansBitForBit) {
  const MatchSetup setup;
  // Angles whose degrees do not read back to the same radians.
  for (double heading : {0.1, 1.0 / 3.0, -2.9, 3.1, std::nextafter(kPi, 0.0), 1e-300}) {
    TurnInput t = aSpunShot(heading, 3.0);
    t.shot.elevation_rad = std::nextafter(0.4, 1.0);
    const WireTurn w = wireTurn(t, HumanSeat{}, setup.game);
    // Through text, as the peer gets it.
    const WireTurn arrived{json::parse(w.turn.dump()), w.player};
    std::string why;
    const auto back = parseWireTurn(arrived, setup, why);
    ASSERT_TRUE(back.has_value()) << why;
    EXPECT_EQ(std::memcmp(&back->shot.heading_rad, &t.shot.heading_rad, sizeof(double)), 0)
        << heading;
    EXPECT_EQ(std::memcmp(&back->shot.elevation_rad, &t.shot.elevation_rad, sizeof(double)), 0);
    EXPECT_EQ(back->shot.speed, t.shot.speed);
    EXPECT_EQ(back->shot.tip.x, t.shot.tip.x);
  }
}

TEST(Protocol, AWireTurnWhoseRadiansDisagreeWithItsDegreesIsRefused) {
  const MatchSetup setup;
  const WireTurn good = wireTurn(aSpunShot(1.0, 3.0), HumanSeat{}, setup.game);
  std::string why;
  ASSERT_TRUE(parseWireTurn(good, setup, why).has_value()) << why;

  // A whole turn round is the same heading.
  WireTurn round = good;
  round.turn["heading_rad"] = 1.0 - 2.0 * kPi;
  EXPECT_TRUE(parseWireTurn(round, setup, why).has_value()) << why;

  for (const auto& [key, value] : std::vector<std::pair<const char*, json>>{
           {"heading_rad", 1.0 + 1e-6},
           {"heading_rad", -1.0},
           {"elevation_rad", 0.0},
           {"elevation_rad", 0.0872664625997164788 + 2.0 * kPi}}) {
    WireTurn w = good;
    w.turn[key] = value;
    why.clear();
    EXPECT_FALSE(parseWireTurn(w, setup, why).has_value()) << key << " " << value;
    EXPECT_FALSE(why.empty());
  }
  for (const char* key : {"heading_rad", "elevation_rad"}) {
    WireTurn w = good;
    w.turn.erase(key);
    EXPECT_FALSE(parseWireTurn(w, setup, why).has_value());
    EXPECT_TRUE(mentions(why, "heading_rad")) << why;
    w = good;
    w.turn[key] = 7.0;
    EXPECT_FALSE(parseWireTurn(w, setup, why).has_value());
    EXPECT_TRUE(mentions(why, key)) << why;
    w.turn[key] = "1.0";
    EXPECT_FALSE(parseWireTurn(w, setup, why).has_value());
    EXPECT_TRUE(mentions(why, key)) << why;
  }
}

TEST(Protocol, AWireTurnIsCheckedAsAScriptTurn) {
  const MatchSetup setup;
  const WireTurn good = wireTurn(aSpunShot(1.0, 3.0), HumanSeat{}, setup.game);
  const std::vector<std::pair<const char*, json>> bad = {
      {"speed", 14.5},
      {"speed", -1.0},
      {"tip", {2.0, 0.0}},
      {"cue", {0.1}},
      {"cue", {"x", 0.0}},
      {"call", {{"ball", 16}, {"pocket", "top-left"}}},
      {"call", {{"ball", 0}, {"pocket", "top-left"}}},
      {"call", {{"ball", 9}, {"pocket", "middle"}}},
      {"push_out", "yes"},
      {"spin", 1.0},
  };
  for (const auto& [key, value] : bad) {
    WireTurn w = good;
    w.turn[key] = value;
    std::string why;
    EXPECT_FALSE(parseWireTurn(w, setup, why).has_value()) << key << " " << value;
    EXPECT_TRUE(mentions(why, key)) << why;
  }
}

TEST(Protocol, ADecisionCarriesNoAngles) {
  const MatchSetup setup;
  TurnInput d;
  d.kind = TurnInput::Kind::Decision;
  const WireTurn w = wireTurn(d, HumanSeat{}, setup.game);
  EXPECT_FALSE(w.turn.contains("heading_rad"));
  std::string why;
  const auto back = parseWireTurn(w, setup, why);
  ASSERT_TRUE(back.has_value()) << why;
  EXPECT_EQ(back->kind, TurnInput::Kind::Decision);
  WireTurn angled = w;
  angled.turn["heading_rad"] = 0.0;
  EXPECT_FALSE(parseWireTurn(angled, setup, why).has_value());
  EXPECT_TRUE(mentions(why, "no angles")) << why;
}

// --- the text of a message, before it is read ---

TEST(Protocol, MessageTextNestedTooDeepIsRefusedBeforeParsing) {
  std::string why;
  std::string deep = "{\"type\":\"hello\",\"x\":";
  for (int i = 0; i < 100000; ++i) deep += '[';
  EXPECT_FALSE(parseMessage(deep, why).has_value());
  EXPECT_TRUE(mentions(why, "nested")) << why;
  // Brackets inside a string are text, not depth.
  const std::string quoted = R"({"type":"refuse","reason":")" + std::string(50, '[') + "\\\"\"}";
  EXPECT_TRUE(parseMessage(quoted, why).has_value()) << why;
  for (const char* bad : {"", "{", "[1]", "{\"type\":1}", "{\"kind\":\"hello\"}", "nul",
                          "{\"type\":\"a\"} x", "\xff\xfe"}) {
    why.clear();
    EXPECT_FALSE(parseMessage(bad, why).has_value()) << bad;
    EXPECT_FALSE(why.empty());
  }
}

TEST(Protocol, PeerTextIsCleanedOfControlCharactersAndCutToTheLimit) {
  EXPECT_EQ(cleanText("\x1b[31mred\r\nnineball online: forged\x07"),
            "[31mrednineball online: forged");
  EXPECT_EQ(cleanText("caf\xc3\xa9 \xc2\x9b"
                      "2J"),
            "caf\xc3\xa9 2J");  // a C1 CSI goes too
  const std::string long_text = std::string(199, 'x') + "\xc3\xa9";
  EXPECT_EQ(cleanText(long_text), std::string(199, 'x')) << "cut at a whole character";
  EXPECT_EQ(cleanText(std::string(500, 'y')).size(), kMostText);
  // A refusal too long to read is cut when sent, never dropped.
  const json refusal = toJson(Refuse{std::string(300, 'r')});
  std::string why;
  const auto back = readMessage(refusal, why);
  ASSERT_TRUE(back.has_value()) << why;
  EXPECT_EQ(std::get<Refuse>(*back).reason, std::string(kMostText, 'r'));
  // A received reason is cleaned too.
  const auto bye = readMessage({{"type", "bye"},
                                {"reason",
                                 "a\x1b]0;t\x07"
                                 "b"},
                                {"finished", false}},
                               why);
  ASSERT_TRUE(bye.has_value()) << why;
  EXPECT_EQ(std::get<Bye>(*bye).reason, "a]0;tb");
}

TEST(Protocol, JoinCodesAndSeatTokensHaveTheirShape) {
  for (int i = 0; i < 50; ++i) {
    const std::string code = makeJoinCode();
    ASSERT_EQ(code.size(), 9u) << code;
    EXPECT_EQ(code[4], '-');
    EXPECT_EQ(code.find_first_of("01OIL"), std::string::npos) << code;
    EXPECT_TRUE(codeMatches(code, code));
    EXPECT_TRUE(isSeatToken(makeSeatToken()));
  }
  EXPECT_NE(makeJoinCode(), makeJoinCode());
  EXPECT_NE(makeSeatToken(), makeSeatToken());
  EXPECT_TRUE(codeMatches("7kq4 zp2m", "7KQ4-ZP2M"));
  EXPECT_FALSE(codeMatches("7KQ4-ZP2N", "7KQ4-ZP2M"));
  EXPECT_FALSE(codeMatches("", "7KQ4-ZP2M"));
  EXPECT_FALSE(codeMatches("", ""));
  EXPECT_FALSE(tokenMatches("", ""));
  EXPECT_FALSE(isSeatToken(std::string(32, 'A')));
  EXPECT_FALSE(isSeatToken(std::string(31, 'a')));
  // A hello's token is empty or 32 hex digits; a welcome's is never empty.
  json hello = toJson(helloFrom("Bo", "X"));
  std::string why;
  hello["token"] = "abc";
  EXPECT_FALSE(readMessage(hello, why).has_value());
  EXPECT_NE(why.find("token"), std::string::npos) << why;
  hello["token"] = "";
  hello["code"] = std::string(kMostCodeChars + 1, 'c');
  EXPECT_FALSE(readMessage(hello, why).has_value());
  EXPECT_NE(why.find("code"), std::string::npos) << why;
  json welcome = toJson(oneOfEach()[2]);
  ASSERT_EQ(welcome["type"], "welcome");
  welcome["token"] = "";
  EXPECT_FALSE(readMessage(welcome, why).has_value());
  EXPECT_NE(why.find("token"), std::string::npos) << why;
}

}  // namespace
}  // namespace nineball::net
