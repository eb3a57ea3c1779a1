// The attacks of issue 46, each against a live host (or, for a hostile host, a real joiner)
// over loopback: a stranger who can reach the port and knows the build must not join, take a
// seat, stall the host or crash either side.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <iostream>

#include "common/log.hpp"
#include "io/snapshot_json.hpp"
#include "net/attack_support.hpp"

namespace nineball::net {
namespace {

using namespace net_test;
using Outcome = OnlineRackResult::Outcome;

// The host breaks softly from its script (nothing falls): the joiner is then to move.
const char* kSoftBreak = R"({"seed": 5, "turns": [{"heading_deg": 0, "speed": 2}]})";
const char* kComputerHost = R"({"seed": 5, "players": {"A": "ai:beginner"}})";

class Attacks : public ::testing::Test {
 protected:
  void SetUp() override {
    setLogLevel("off");
    port_ = freePort();
    ASSERT_NE(port_, 0);
  }
  void TearDown() override { setLogLevel("warn"); }

  // Connects a raw peer, waiting for the host to listen.
  std::unique_ptr<RawPeer> peer() {
    auto p = std::make_unique<RawPeer>();
    EXPECT_TRUE(connectSoon(*p, port_));
    return p;
  }
  // A refusal of `hello` by name.
  Answer refusalOf(const json& hello) {
    auto p = peer();
    p->send(hello);
    return p->awaitRefusal(kAttackBound, true);
  }

  unsigned short port_ = 0;
};

TEST_F(Attacks, AStrangerWithoutTheCodeIsRefusedAndTheHostWaitsOn) {
  RackThread host(hostOf(port_, kComputerHost));
  // Today's hello of the build, which anyone can learn from `nineball --version`.
  const Answer none = refusalOf(json{
      {"type", "hello"}, {"protocol", kProtocolVersion}, {"build", buildId()}, {"name", "Eve"}});
  EXPECT_EQ(none.kind, Answer::Kind::Refused);
  const Answer missing = refusalOf(helloWith(""));
  EXPECT_EQ(missing.kind, Answer::Kind::Refused);
  EXPECT_NE(missing.reason.find("no join code"), std::string::npos) << missing.reason;
  const Answer wrong = refusalOf(helloWith("AAAA-BBBB"));
  EXPECT_NE(wrong.reason.find("wrong join code"), std::string::npos) << wrong.reason;
  EXPECT_TRUE(wrong.closed_after_refusal);
  EXPECT_FALSE(host.finished()) << "a stranger ended the host";
  // The code is compared without case and dashes: the friend gets in.
  auto friend_peer = peer();
  EXPECT_TRUE(sitDown(*friend_peer, helloWith("7kq4zp2m"), false).has_value());
}

TEST_F(Attacks, RepeatedWrongCodesFromOneAddressAreSlowedDown) {
  RackThread host(hostOf(port_, kComputerHost));
  for (int i = 0; i < 3; ++i) {
    EXPECT_NE(refusalOf(helloWith("WRONG-" + std::to_string(i))).reason.find("wrong join code"),
              std::string::npos);
  }
  // The fourth wrong guess sets a wait; meanwhile even the right code is not looked at.
  refusalOf(helloWith("WRONG-4"));
  const Answer slowed = refusalOf(helloWith(kCode));
  EXPECT_NE(slowed.reason.find("too many wrong join codes"), std::string::npos) << slowed.reason;
  // Once the wait is over, the right code gets in.
  std::optional<Seating> seated;
  for (double until = now() + kAttackBound; !seated && now() < until;) {
    auto p = peer();
    seated = sitDown(*p, helloWith(kCode), false);
    if (!seated) std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  EXPECT_TRUE(seated.has_value());
}

TEST_F(Attacks, AnIntruderWithTheCodeCannotTakeASeatThatIsTaken) {
  RackThread host(hostOf(port_, kComputerHost));
  auto seated = peer();
  const auto seat = sitDown(*seated, helloWith(kCode, "", "human", "Seated"), true);
  ASSERT_TRUE(seat.has_value());
  const std::string token = seat->welcome.value("token", "");
  ASSERT_TRUE(isSeatToken(token)) << seat->welcome.dump();
  // With the build and the code, but not the token: refused, and the seated player stays.
  const Answer intruder = refusalOf(helloWith(kCode, "", "human", "Intruder"));
  EXPECT_NE(intruder.reason.find("the seat is taken"), std::string::npos) << intruder.reason;
  const Answer guess = refusalOf(helloWith(kCode, std::string(32, 'a')));
  EXPECT_NE(guess.reason.find("the seat is taken"), std::string::npos) << guess.reason;
  seated->keepAlive();
  seated->poll();
  EXPECT_FALSE(seated->closed()) << "an intruder displaced the seated player";
  // The player itself, on a new connection with its token, takes the seat back.
  auto back = peer();
  const auto again = sitDown(*back, helloWith(kCode, token, "human", "Seated"), false);
  ASSERT_TRUE(again.has_value()) << "the seat's own token was refused";
  EXPECT_EQ(again->welcome["turns"].size(), 1u) << "the rack so far: the host's break";
  EXPECT_EQ(again->welcome["token"], token);
  back->send(json{{"type", "bye"}, {"reason", "done"}, {"finished", false}});
  ASSERT_TRUE(host.result(kAttackBound).has_value());
}

TEST_F(Attacks, AByeFinishedBeforeTheRackIsOverIsAQuit) {
  RackThread host(hostOf(port_, kComputerHost));
  auto seated = peer();
  ASSERT_TRUE(sitDown(*seated, helloWith(kCode), true).has_value());
  // The host's break is not yet agreed: no rack of the joiner's can be over here.
  seated->send(json{{"type", "bye"}, {"reason", "the rack is played"}, {"finished", true}});
  const auto result = host.result(kAttackBound);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->outcome, Outcome::LinkLost) << result->why;
  EXPECT_NE(result->why.find("left"), std::string::npos) << result->why;
}

// Agrees the host's last hash and sends a turn of the joiner's, labelled `player`.
json joinerTurnAfterTheBreak(RawPeer& seated, const Seating& seat, const std::string& player) {
  const json& hash = seat.after.back();
  seated.send(json{{"type", "hash"}, {"index", hash["index"]}, {"hash", hash["hash"]}});
  Rng rng(3);
  return json{{"type", "turn"}, {"index", 1}, {"turn", plausibleTurn(rng)}, {"player", player}};
}

TEST_F(Attacks, AHumanSeatCannotPassItsTurnsOffAsTheComputers) {
  RackThread host(hostOf(port_, kSoftBreak));
  auto seated = peer();
  const auto seat = sitDown(*seated, helloWith(kCode, "", "human"), true);
  ASSERT_TRUE(seat.has_value());
  seated->send(joinerTurnAfterTheBreak(*seated, *seat, "ai:master"));
  const Answer a = seated->awaitRefusal(kAttackBound, true);
  EXPECT_EQ(a.kind, Answer::Kind::Refused);
  EXPECT_NE(a.reason.find("labelled ai:master"), std::string::npos) << a.reason;
}

TEST_F(Attacks, APeerThatNeverPlaysItsTurnIsGivenUp) {
  OnlineRackOptions o = hostOf(port_, kSoftBreak);
  o.turn_s = 1.0;
  RackThread host(o);
  auto seated = peer();
  const auto seat = sitDown(*seated, helloWith(kCode), true);
  ASSERT_TRUE(seat.has_value());
  const json& hash = seat->after.back();
  seated->send(json{{"type", "hash"}, {"index", hash["index"]}, {"hash", hash["hash"]}});
  // It answers (pings) but never plays.
  const double start = now();
  while (!host.finished() && now() - start < kAttackBound) {
    seated->keepAlive();
    seated->poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const auto result = host.result(1.0);
  ASSERT_TRUE(result.has_value()) << "the host waited on for the turn";
  EXPECT_EQ(result->outcome, Outcome::LinkLost);
  EXPECT_NE(result->why.find("no turn within 1 s"), std::string::npos) << result->why;
}

TEST_F(Attacks, SilentSocketsDoNotKeepAJoinerOut) {
  RackThread host(hostOf(port_, kComputerHost));
  std::vector<std::unique_ptr<RawPeer>> silent;
  for (int i = 0; i < 8; ++i) silent.push_back(peer());
  const double start = now();
  OnlineRackOptions joiner;
  joiner.side = Side::Joiner;
  joiner.address = {"127.0.0.1", port_};
  joiner.script = scriptOf(R"({"players": {"B": "ai:beginner"}})");
  joiner.code = kCode;
  joiner.wait_s = 4 * kAttackBound;
  std::atomic<bool> quit{false};
  joiner.quit = &quit;
  joiner.on_seat_token = [&](const std::string&) { quit = true; };  // welcomed: enough
  RackThread join(joiner);
  const auto result = join.result(4 * kAttackBound);
  ASSERT_TRUE(result.has_value());
  const double took = now() - start;
  std::cout << "[attacks] 8 silent sockets: the joiner was welcomed after " << took << " s\n";
  EXPECT_EQ(result->outcome, Outcome::Quit) << result->why;
  EXPECT_LT(took, kPromptly) << "silent sockets held the joiner out";
}

TEST_F(Attacks, AFrameDrippedAByteAtATimeIsNotASignOfLife) {
  RackThread host(hostOf(port_, kComputerHost));
  auto seated = peer();
  ASSERT_TRUE(sitDown(*seated, helloWith(kCode), false).has_value());
  seated->sendRaw(lengthPrefix(256 * 1024));
  const double start = now();
  while (!seated->closed() && now() - start < 4 * kAttackBound) {
    seated->sendRaw("x", 0.1);  // one byte every 50 ms, never a whole message
    seated->poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const double held = now() - start;
  std::cout << "[attacks] a dripped frame held the link " << held << " s (silence limit 1 s)\n";
  EXPECT_TRUE(seated->closed()) << "the host took the drip for a live peer";
  EXPECT_LT(held, 1.0 + kAttackBound / 2);
}

TEST_F(Attacks, HealsAreLimitedPerRack) {
  OnlineRackOptions o = hostOf(port_, kComputerHost);
  o.most_heals = 2;
  RackThread host(o);
  std::string token;
  int states = 0;
  for (int round = 0; round < 5 && !host.finished(); ++round) {
    auto p = peer();
    const auto seat = sitDown(*p, helloWith(kCode, token), true);
    if (!seat) break;
    if (token.empty()) token = seat->welcome["token"];
    json wrong = seat->after.back();
    std::string h = wrong["hash"];
    h[0] = h[0] == '0' ? '1' : '0';
    wrong["hash"] = h;
    p->send(wrong);
    const json m = p->next(kAttackBound);
    states += !m.is_null() && m.value("type", "") == "state";
  }  // each round drops the link and rejoins: a heal each time
  const auto result = host.result(kAttackBound);
  ASSERT_TRUE(result.has_value()) << "the host healed on and on";
  EXPECT_EQ(result->outcome, Outcome::OutOfStep) << result->why;
  EXPECT_EQ(states, 2);
}

TEST_F(Attacks, ARefusalIsCutToWhatTheOtherSideReads) {
  RackThread host(hostOf(port_, kComputerHost));
  json hello = helloWith(kCode);
  hello["build"] = std::string(kMostText, 'b');  // another build, as long as a build may be
  auto p = peer();
  p->send(hello);
  const json m = p->next(kAttackBound);
  ASSERT_FALSE(m.is_null());
  std::string why;
  const auto read = readMessage(m, why);
  ASSERT_TRUE(read.has_value()) << "the joiner cannot read the refusal: " << why;
  ASSERT_TRUE(std::holds_alternative<Refuse>(*read));
  EXPECT_LE(std::get<Refuse>(*read).reason.size(), kMostText);
  EXPECT_NE(std::get<Refuse>(*read).reason.find("bbbb"), std::string::npos);
}

TEST_F(Attacks, BrokenStreamsAndFloodsAreAnsweredWithARefusal) {
  RackThread host(hostOf(port_, kComputerHost));
  const std::string cases[] = {framedText("not json \x1b[2J"), lengthPrefix(0),
                               lengthPrefix(1 << 30)};
  for (const std::string& bytes : cases) {
    auto p = peer();
    p->sendRaw(bytes);
    const Answer a = p->awaitRefusal(kAttackBound, false);
    EXPECT_EQ(a.kind, Answer::Kind::Refused) << json(bytes.substr(4)).dump();
    EXPECT_EQ(a.reason.find('\x1b'), std::string::npos) << a.reason;
  }
  auto p = peer();
  std::string flood;
  for (int i = 0; i < 200; ++i) flood += framedText(R"({"type":"ping"})");
  p->sendRaw(flood);
  const Answer a = p->awaitRefusal(kAttackBound, false);
  EXPECT_EQ(a.kind, Answer::Kind::Refused);
  EXPECT_NE(a.reason.find("flooded"), std::string::npos) << a.reason;
}

TEST_F(Attacks, APeersWordsReachTheLogWithoutControlCharacters) {
  RackThread host(hostOf(port_, kComputerHost));
  auto seated = peer();
  ASSERT_TRUE(sitDown(*seated, helloWith(kCode), false).has_value());
  seated->send(json{{"type", "bye"},
                    {"reason", "\x1b[31m\nnineball online: forged line\r"},
                    {"finished", false}});
  const auto result = host.result(kAttackBound);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->why.find_first_of("\x1b\n\r"), std::string::npos) << json(result->why).dump();
}

// --- a hostile host against a real joiner ---

class HostileHost : public Attacks {
 protected:
  OnlineRackOptions joinerOptions() {
    OnlineRackOptions j;
    j.side = Side::Joiner;
    j.address = {"127.0.0.1", port_};
    j.script = scriptOf(R"({"players": {"B": "ai:beginner"}})");
    j.code = kCode;
    j.wait_s = kAttackBound;
    j.rejoin_s = 1.0;
    return j;
  }
  // Welcomes the joiner with no turns, plays the host's break, answers the joiner's hash with
  // a wrong one and sends `state` (the host's own after the break, changed by `tamper`): the
  // joiner's answer.
  json healWith(const std::function<void(json&)>& tamper) {
    FakeHost fake(port_);
    RackThread joiner(joinerOptions());
    FakeLink link = fake.accept(kAttackBound);
    if (!link.link) return "no joiner";
    const json hello = link.next(kAttackBound);
    if (hello.value("type", "") != "hello") return "no hello";
    const std::string text = R"({"seed": 5, "turns": []})";
    const io::MatchScript script = scriptOf(text);
    Match match(script.setup);
    Lockstep lockstep(Side::Host, script.setup);
    Welcome w =
        welcomeFrom("Mallory", matchPart(json::parse(text)), Race{}, lockstep, makeSeatToken());
    link.send(w);
    TurnInput brk;
    brk.shot.speed = 2.0;
    TurnMessage t;
    const CheckedTurn turn = lockstep.localTurn(brk, HumanSeat{}, t);
    match.play(turn.input);
    link.send(t);
    HashMessage h = lockstep.played(t.turn, match.snapshot());
    h.hash ^= 1;  // out of step
    link.send(h);
    json state = io::snapshotToJson(match.snapshot());
    tamper(state);
    link.send(StateMessage{0, state});
    for (double until = now() + kAttackBound; now() < until;) {
      const json m = link.next(until - now());
      if (m.is_null() || m.value("type", "") == "refuse") {
        const auto r = joiner.result(4 * kAttackBound);
        EXPECT_TRUE(r.has_value());
        if (r) {
          EXPECT_NE(r->outcome, Outcome::InStep) << r->why;
        }
        return m;
      }
    }
    return nullptr;
  }
};

TEST_F(HostileHost, AHealThatCannotBeTheRackIsRefusedByName) {
  const struct {
    const char* what;
    std::function<void(json&)> tamper;
    const char* reason;
  } cases[] = {
      {"the cue ball in hand left on the table", [](json& s) { s["cue_pocketed"] = true; },
       "in hand is on the table"},
      {"every ball at one point",
       [](json& s) {
         for (auto& b : s["balls"]) b["x"] = 0.3, b["y"] = 0.1;
       },
       "overlaps"},
      {"the cue ball off the table", [](json& s) { s["balls"][0]["x"] = 2.2; }, "off the table"},
      {"a winner before the end", [](json& s) { s["rack"]["winner"] = "A"; }, "winner"},
      {"a million fouls",
       [](json& s) {
         s["rack"]["fouls"] = {1000000, 0};
       },
       "fouls"},
      {"a ball faster than any cue", [](json& s) { s["balls"][3]["vx"] = 90.0; }, "faster"},
  };
  for (const auto& c : cases) {
    const json answer = healWith(c.tamper);
    ASSERT_TRUE(answer.is_object()) << c.what << ": " << answer.dump();
    EXPECT_EQ(answer.value("type", ""), "refuse") << c.what;
    EXPECT_NE(answer.value("reason", "").find(c.reason), std::string::npos)
        << c.what << ": " << answer.dump();
  }
}

TEST_F(HostileHost, AHostsRefusalIsShownCleanAndEndsTheJoinWithItsReason) {
  FakeHost fake(port_);
  RackThread joiner(joinerOptions());
  FakeLink link = fake.accept(kAttackBound);
  ASSERT_TRUE(link.link);
  const json hello = link.next(kAttackBound);
  ASSERT_EQ(hello.value("type", ""), "hello");
  EXPECT_EQ(hello.value("code", ""), kCode);
  link.send(Refuse{"\x1b]0;owned\x07 wrong join code"});
  link.link->flush(1.0);
  const auto r = joiner.result(4 * kAttackBound);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->outcome, Outcome::Refused) << r->why;
  EXPECT_NE(r->why.find("wrong join code"), std::string::npos) << r->why;
  EXPECT_EQ(r->why.find_first_of("\x1b\x07"), std::string::npos) << json(r->why).dump();
}

// A welcome whose turns go on after the rack was over (here the 9 is potted with the first
// shot): refused before anything more is simulated.
TEST_F(HostileHost, AWelcomeWithTurnsAfterTheRackEndedIsRefused) {
  const std::string text = R"({"seed": 5, "turns": [],
      "balls": [{"id": 0, "x": 0.6, "y": 0.3}, {"id": 9, "x": 1.0, "y": 0.5}]})";
  const io::MatchScript script = scriptOf(text);
  Match match(script.setup);
  Lockstep lockstep(Side::Host, script.setup);
  TurnInput pot;
  pot.shot.heading_rad = std::atan2(0.2, 0.4);
  pot.shot.speed = 2.0;
  pot.shot.tip = {0.0, -0.3};  // a little draw: the cue ball stays out of the pocket
  TurnMessage m;
  match.play(lockstep.localTurn(pot, HumanSeat{}, m).input);
  ASSERT_TRUE(match.rack().over()) << "the 9 was not potted: no rack ended to test";
  lockstep.played(m.turn, match.snapshot());
  Welcome w =
      welcomeFrom("Mallory", matchPart(json::parse(text)), Race{}, lockstep, makeSeatToken());
  w.turns.push_back(w.turns.back());
  w.hashes.push_back(w.hashes.back());

  FakeHost fake(port_);
  RackThread joiner(joinerOptions());
  FakeLink link = fake.accept(kAttackBound);
  ASSERT_TRUE(link.link);
  ASSERT_EQ(link.next(kAttackBound).value("type", ""), "hello");
  link.send(w);
  const json answer = link.next(kAttackBound);
  ASSERT_TRUE(answer.is_object());
  EXPECT_EQ(answer.value("type", ""), "refuse");
  EXPECT_NE(answer.value("reason", "").find("turns[1] comes after the rack was over"),
            std::string::npos)
      << answer.dump();
  ASSERT_TRUE(joiner.result(4 * kAttackBound).has_value());
}

TEST_F(HostileHost, AWelcomeReplayHearsCtrlCWithinASecond) {
  FakeHost fake(port_);
  std::atomic<bool> quit{false};
  OnlineRackOptions o = joinerOptions();
  o.quit = &quit;
  RackThread joiner(o);
  FakeLink link = fake.accept(kAttackBound);
  ASSERT_TRUE(link.link);
  ASSERT_EQ(link.next(kAttackBound).value("type", ""), "hello");
  // A rack of hard shots to replay, each a few seconds of simulated time.
  // Snooker (fouls do not end a frame) on a cloth that barely slows the balls. The replay is
  // still quick here (the number printed): this checks the quit is heard, not that it cuts
  // a long replay short.
  const std::string text = R"({"game": "snooker", "seed": 5, "turns": [],
      "physics": {"preset": "snooker", "rolling_friction": 0.0005}})";
  const io::MatchScript script = scriptOf(text);
  Match match(script.setup);
  Lockstep lockstep(Side::Host, script.setup);
  // Up to 16 turns of hard shots (a decision when one is due, the cue ball placed when it must
  // be); a turn the rules refuse is left out.
  const double made = now();
  for (int i = 0; i < 100 && lockstep.turns().size() < 16 && !match.rack().over(); ++i) {
    TurnInput t;
    if (match.rack().awaitingDecision()) {
      t.kind = TurnInput::Kind::Decision;
    } else {
      t.shot.speed = 12.0;
      t.shot.heading_rad = 0.37 * i;
      if (match.cueMustBePlaced()) t.cue = Vec2{-1.15, 0.04 * (i % 5)};  // in the D
    }
    TurnMessage m;
    const CheckedTurn turn = lockstep.localTurn(t, HumanSeat{}, m);
    try {
      match.play(turn.input);
    } catch (const IllegalAction&) {
      continue;
    }
    if (!match.world().atRest()) break;
    lockstep.played(m.turn, match.snapshot());
  }
  const double replay_s = now() - made;
  link.send(
      welcomeFrom("Mallory", matchPart(json::parse(text)), Race{}, lockstep, makeSeatToken()));
  link.link->flush(1.0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const double asked = now();
  quit = true;
  const auto r = joiner.result(4 * kAttackBound);
  ASSERT_TRUE(r.has_value());
  const double took = now() - asked;
  std::cout << "[attacks] a welcome of " << lockstep.turns().size() << " turns (" << replay_s
            << " s to play here): the joiner left " << took << " s after Ctrl-C\n";
  EXPECT_LT(took, kCtrlC);
}

}  // namespace
}  // namespace nineball::net
