// `nineball online`: two real processes on the loopback play racks together.
#include <gtest/gtest.h>

#include <SFML/Network/TcpListener.hpp>
#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "app/cli_runner.hpp"
#include "net/connection.hpp"
#include "net/free_port.hpp"
#include "net/handshake.hpp"
#include "net/protocol.hpp"

namespace {

using nineball::testing::freePort;

using nineball::testing::CliOutcome;
using nineball::testing::runNineball;
using nineball::testing::shellQuoted;
using nineball::testing::TempFile;
using nlohmann::json;

struct Pair {
  CliOutcome host;
  CliOutcome join;
};

// The host in a thread, the joiner here (it keeps trying until the host listens).
Pair playOnline(const std::string& host_script, const std::string& join_script,
                const std::string& host_flags = "", const std::string& join_flags = "") {
  const unsigned short port = freePort();
  TempFile hs(host_script);
  TempFile js(join_script);
  Pair r;
  std::thread host([&] {
    r.host = runNineball("online --host " + std::to_string(port) + " --code TEST-CODE --wait 120 " +
                         host_flags + " " + shellQuoted(hs.path()));
  });
  r.join = runNineball("online --join 127.0.0.1:" + std::to_string(port) + " --code TEST-CODE " +
                       join_flags + " " + shellQuoted(js.path()));
  host.join();
  return r;
}

json withoutHashes(json doc) {
  doc.erase("hashes");
  return doc;
}

json matchResult(const std::string& script) {
  const CliOutcome m = nineball::testing::runOnDocument("match", script);
  EXPECT_EQ(m.status, 0) << m.err;
  return json::parse(m.out);
}

struct GameCase {
  const char* game;
  const char* extra;  // more of the host's script
  const char* a;
  const char* b;
};

void PrintTo(const GameCase& c, std::ostream* os) {
  *os << c.game << " " << c.a << " vs " << c.b;
}

class OnlineGames : public ::testing::TestWithParam<GameCase> {};

// Each side plays its own seat (here both computers); the rack comes out on both sides turn
// for turn, hash for hash, and as `nineball match` plays the same two players at one table.
TEST_P(OnlineGames, PlayWholeRacksInStepAndAsAtOneTable) {
  const GameCase& c = GetParam();
  const std::string setup = std::string(R"({"game": ")") + c.game + R"(", "seed": 5)" + c.extra;
  const Pair p = playOnline(setup + R"(, "players": {"A": ")" + c.a + R"("}})",
                            R"({"players": {"B": ")" + std::string(c.b) + R"("}})");
  ASSERT_EQ(p.host.status, 0) << p.host.err;
  ASSERT_EQ(p.join.status, 0) << p.join.err;
  const json host = json::parse(p.host.out);
  const json join = json::parse(p.join.out);
  ASSERT_EQ(host["hashes"].size(), host["turns"].size());
  EXPECT_GT(host["turns"].size(), 1u);
  EXPECT_EQ(host["hashes"], join["hashes"]);
  EXPECT_EQ(host, join);
  const json local =
      matchResult(setup + R"(, "players": {"A": ")" + c.a + R"(", "B": ")" + c.b + R"("}})");
  EXPECT_EQ(withoutHashes(host), local);
  EXPECT_FALSE(host["winner"].is_null()) << "the rack was played to its end";
}

INSTANTIATE_TEST_SUITE_P(EveryGame, OnlineGames,
                         ::testing::Values(GameCase{"nine-ball", "", "ai:pro", "ai:club"},
                                           GameCase{"eight-ball", "", "ai:pro", "ai:club"},
                                           GameCase{"ten-ball", "", "ai:master", "ai:master"},
                                           GameCase{"three-cushion", R"(, "points": 1)",
                                                    "ai:advanced", "ai:advanced"},
                                           GameCase{"snooker", "", "ai:master", "ai:master"}),
                         [](const auto& param_info) {
                           std::string name = param_info.param.game;
                           name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
                           return name;
                         });

// People's turns from scripts: each side's script holds its own player's turns in order.
TEST(OnlineCli, EachSideTakesItsTurnsFromItsScript) {
  const std::string turns = R"([{"heading_deg": 0, "speed": 10},
      {"push_out": true, "heading_deg": 90, "speed": 0.4}, {"decision": "pass"},
      {"heading_deg": 180, "speed": 1.5}])";
  const json whole = json::parse(R"({"rules": "wpa", "seed": 7, "turns": )" + turns + "}");
  const json local = matchResult(whole.dump());
  ASSERT_EQ(local["turns"].size(), 4u);
  json a = json::array();
  json b = json::array();
  for (std::size_t i = 0; i < local["turns"].size(); ++i) {
    (local["turns"][i]["shooter"] == "A" ? a : b).push_back(whole["turns"][i]);
  }
  ASSERT_FALSE(b.empty());
  json host = whole;
  host["turns"] = a;
  const Pair p = playOnline(host.dump(), json{{"turns", b}}.dump());
  ASSERT_EQ(p.host.status, 0) << p.host.err;
  ASSERT_EQ(p.join.status, 0) << p.join.err;
  EXPECT_EQ(json::parse(p.host.out), json::parse(p.join.out));
  EXPECT_EQ(withoutHashes(json::parse(p.host.out)), local);
}

const char* kHostPro = R"({"game": "nine-ball", "seed": 3, "players": {"A": "ai:pro"}})";
const char* kJoinClub = R"({"players": {"B": "ai:club"}})";

// A joiner knocked out of step (a ball moved 1 um after turn 2) takes the host's state whole
// and the rack goes on in step: the same hashes on both sides from there.
TEST(OnlineCli, AStateOutOfStepIsHealedByTheHostsState) {
  const Pair p = playOnline(kHostPro, kJoinClub, "", "--test-nudge-after 2");
  ASSERT_EQ(p.host.status, 0) << p.host.err;
  ASSERT_EQ(p.join.status, 0) << p.join.err;
  EXPECT_NE(p.host.err.find("healed 1 time"), std::string::npos) << p.host.err;
  EXPECT_NE(p.join.err.find("healed 1 time"), std::string::npos) << p.join.err;
  EXPECT_EQ(json::parse(p.host.out), json::parse(p.join.out));
}

// A link lost in the middle of the rack comes back: the joiner connects again, replays the
// turns so far to the same position, and the rack ends as it would have without the break.
TEST(OnlineCli, ALostLinkRejoinsAndTheRackGoesOnWhereItWas) {
  const Pair whole = playOnline(kHostPro, kJoinClub);
  const Pair broken = playOnline(kHostPro, kJoinClub, "", "--test-drop-before 3");
  ASSERT_EQ(broken.host.status, 0) << broken.host.err;
  ASSERT_EQ(broken.join.status, 0) << broken.join.err;
  EXPECT_EQ(json::parse(broken.host.out), json::parse(whole.host.out));
  EXPECT_EQ(json::parse(broken.join.out), json::parse(whole.join.out));
}

// The joiner's process dies in the middle of the rack; a new one joins and finishes it.
TEST(OnlineCli, ANewProcessRejoinsARackInTheMiddle) {
  const unsigned short port = freePort();
  TempFile hs(kHostPro);
  TempFile js(kJoinClub);
  CliOutcome host;
  std::thread t([&] {
    host = runNineball("online --host " + std::to_string(port) +
                       " --code TEST-CODE --wait 60 --rejoin 60 " + shellQuoted(hs.path()));
  });
  // The seat token the first process was welcomed with is kept in a file the second reads.
  TempFile token("");
  const std::string join = "online --join 127.0.0.1:" + std::to_string(port) +
                           " --code TEST-CODE --seat-token " + shellQuoted(token.path()) + " ";
  const CliOutcome dead = runNineball(join + "--test-quit-before 3 " + shellQuoted(js.path()));
  const CliOutcome second = runNineball(join + shellQuoted(js.path()));
  t.join();
  EXPECT_NE(dead.status, 0);
  EXPECT_TRUE(dead.out.empty());
  ASSERT_EQ(second.status, 0) << second.err;
  ASSERT_EQ(host.status, 0) << host.err;
  const json h = json::parse(host.out);
  EXPECT_EQ(h, json::parse(second.out));
  EXPECT_GT(h["turns"].size(), 3u);
}

// Ctrl-C on one side: the other hears that its player quit and ends the rack (exit 5) without
// waiting for a rejoin.
TEST(OnlineCli, APlayerWhoQuitsTellsTheOtherSide) {
  const unsigned short port = freePort();
  TempFile hs(R"({"game": "snooker", "seed": 5, "players": {"A": "ai:master"}})");
  TempFile js(R"({"players": {"B": "ai:master"}})");
  CliOutcome host;
  std::thread t([&] {
    host = runNineball("online --host " + std::to_string(port) +
                       " --code TEST-CODE --wait 60 --rejoin 60 " + shellQuoted(hs.path()));
  });
  const auto started = std::chrono::steady_clock::now();
  const CliOutcome quitter = runNineball("online --join 127.0.0.1:" + std::to_string(port) +
                                             " --code TEST-CODE " + shellQuoted(js.path()),
                                         "/dev/null", "timeout --preserve-status -s INT 1 ");
  t.join();
  EXPECT_EQ(quitter.status, 5) << quitter.err;
  EXPECT_NE(quitter.err.find("quit before the rack was over"), std::string::npos) << quitter.err;
  EXPECT_EQ(host.status, 5) << host.err;
  EXPECT_NE(host.err.find("the other player left: the other player quit"), std::string::npos)
      << host.err;
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(30))
      << "the host did not wait out the rejoin time";
}

// Nobody comes: the host gives up after --wait and says so (exit 5, nothing on stdout).
TEST(OnlineCli, AHostNobodyJoinsGivesUp) {
  TempFile hs(kHostPro);
  const CliOutcome r = runNineball("online --host " + std::to_string(freePort()) + " --wait 1 " +
                                   shellQuoted(hs.path()));
  EXPECT_EQ(r.status, 5);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("nobody joined"), std::string::npos) << r.err;
}

// A peer of another build is refused by name at the handshake; the host then ends with 2.
TEST(OnlineCli, APeerOfAnotherBuildIsRefusedByName) {
  const unsigned short port = freePort();
  TempFile hs(kHostPro);
  CliOutcome host;
  std::thread t([&] {
    host = runNineball("online --host " + std::to_string(port) + " --code TEST-CODE --wait 3 " +
                       shellQuoted(hs.path()));
  });
  std::unique_ptr<sf::TcpSocket> socket;
  std::string why;
  for (int i = 0; i < 100 && !socket; ++i) {
    socket = nineball::net::connectTo({"127.0.0.1", port}, 1.0, why);
    if (!socket) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(socket) << why;
  auto now = [] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  };
  nineball::net::Connection link(std::move(socket), now());
  nineball::net::Hello eve = nineball::net::helloFrom("Eve", "TEST-CODE");
  eve.build = "nineball 0.0.1 (elsewhere)";
  link.send(nineball::net::toJson(eve));
  std::string reason;
  for (int i = 0; i < 2000 && reason.empty() && !link.closed(); ++i) {
    for (const json& m : link.pump(now())) {
      if (m["type"] == "refuse") reason = m["reason"];
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  t.join();
  EXPECT_NE(reason.find("nineball 0.0.1 (elsewhere)"), std::string::npos) << reason;
  EXPECT_NE(reason.find(nineball::net::buildId()), std::string::npos) << reason;
  EXPECT_EQ(host.status, 2) << host.err;
  EXPECT_NE(host.err.find("refused the other side"), std::string::npos) << host.err;
}

// Issue 46: the host prints the line to join with, its code made at random; a joiner with a
// wrong code is refused by the host and says so (exit 2), and the host waits on.
TEST(OnlineCli, AJoinerWithAWrongCodeIsRefusedAndExitsTwo) {
  const unsigned short port = freePort();
  TempFile hs(kHostPro);
  TempFile js(kJoinClub);
  CliOutcome host;
  std::thread t([&] {
    host = runNineball("online --host " + std::to_string(port) + " --wait 4 " +
                       shellQuoted(hs.path()));
  });
  const CliOutcome wrong = runNineball("online --join 127.0.0.1:" + std::to_string(port) +
                                       " --code AAAA-BBBB --wait 20 " + shellQuoted(js.path()));
  t.join();
  EXPECT_EQ(wrong.status, 2) << wrong.err;
  EXPECT_NE(wrong.err.find("the host refused: wrong join code"), std::string::npos) << wrong.err;
  EXPECT_EQ(host.status, 5) << host.err;
  const auto line = host.err.find("join with nineball --join ");
  ASSERT_NE(line, std::string::npos) << host.err;
  const auto code = host.err.find(" --code ", line);
  ASSERT_NE(code, std::string::npos) << host.err;
  const std::string made = host.err.substr(code + 8, 9);
  EXPECT_EQ(made[4], '-') << made;
  EXPECT_EQ(made.find_first_of("01OIL"), std::string::npos) << made;
  const CliOutcome no_code =
      runNineball("online --join 127.0.0.1:" + std::to_string(port) + " " + shellQuoted(js.path()));
  EXPECT_EQ(no_code.status, 2);
  EXPECT_NE(no_code.err.find("--code"), std::string::npos) << no_code.err;
}

TEST(OnlineCli, BadCommandLinesExitTwoWithTheReason) {
  TempFile script(kHostPro);
  const std::string s = " " + shellQuoted(script.path());
  const struct {
    std::string args;
    const char* says;
  } cases[] = {
      {"online" + s, "give one of --host PORT or --join"},
      {"online --host 47047 --join 127.0.0.1" + s, "give one of"},
      {"online --host 0" + s, "outside 1-65535"},
      {"online --host 70000" + s, "outside 1-65535"},
      {"online --host http" + s, "not a number"},
      {"online --join :47047" + s, "no host"},
      {"online --join 127.0.0.1:x" + s, "not a number"},
      {"online --host 47047 /nonexistent.json", "nonexistent"},
  };
  for (const auto& c : cases) {
    const CliOutcome r = runNineball(c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args;
  }
  TempFile bad(R"({"game": "nine-ball", "turns": [{"heading_deg": 0}]})");
  const CliOutcome r = runNineball("online --host 47047 " + shellQuoted(bad.path()));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("turns[0]"), std::string::npos) << r.err;
}

}  // namespace
