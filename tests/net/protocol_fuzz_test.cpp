// A seeded campaign of malformed and hostile messages against a LIVE host (net::playOnlineRack
// in a thread, on a free loopback port), over many connections: before the hello, after a good
// hello, and from intruders while a player holds the seat. Every burst must be refused (a
// refuse message, or the link closed) within a bound, the host must neither crash nor hang,
// and at the end a legitimate joiner must play the rack out in step with it.
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <thread>

#include "common/log.hpp"
#include "io/snapshot_json.hpp"
#include "net/handshake.hpp"
#include "net/hostile_messages.hpp"
#include "net/live_host.hpp"
#include "net/online_rack.hpp"
#include "net/raw_peer.hpp"

namespace nineball::net {
namespace {

using namespace net_test;
using Kind = Answer::Kind;

// The sanitizer build runs several times slower: fewer connections, longer bounds.
#ifdef NINEBALL_SANITIZED
constexpr int kConnectionsBeforeHello = 300;
constexpr int kConnectionsAfterHello = 300;
constexpr int kIntruders = 60;
constexpr double kAnswerBound = 20.0;  // s for the host to refuse a burst
constexpr double kRackBound = 300.0;   // s for the last rack to be played out
#else
constexpr int kConnectionsBeforeHello = 700;
constexpr int kConnectionsAfterHello = 700;
constexpr int kIntruders = 150;
// Every refusal is prompt (a silent peer is dropped after the host's 0.5 s silence limit),
// well before the handshake's 5 s: a burst the host let through to that limit fails.
constexpr double kAnswerBound = 3.0;
constexpr double kRackBound = 60.0;
#endif
// Bursts the host can only close on silence (truncated frames, silent peers) cost a silence
// limit each: a few of them are enough.
constexpr int kMostSlowBursts = 12;
constexpr std::uint64_t kFuzzSeed = 0x5eedf00d;
// A host that fails this often is broken: the campaign stops rather than wait out each bound.
constexpr int kMostFailures = 10;

// The host's link limits: silent peers are dropped fast, so they do not stall the campaign.
LinkLimits hostLimits() {
  LinkLimits l;
  l.silence_s = 0.5;
  l.ping_s = 0.1;
  return l;
}

// What the campaign sent and heard.
struct Tally {
  int connections = 0;
  int messages = 0;
  int refused = 0;
  int closed = 0;
  int unanswered = 0;  // neither refused nor closed within the bound: the test fails
  int failed = 0;      // unanswered, refused without the reason's name, or healed without a state
  int reported = 0;
  double slowest = 0.0;
  std::string slowest_kind;
  std::map<std::string, int> kinds;

  void print(const std::string& phase) const {
    std::cout << "[fuzz] " << phase << ": " << connections << " connections, " << messages
              << " messages, " << refused << " refused by message, " << closed << " closed, "
              << unanswered << " unanswered; slowest answer " << slowest << " s (" << slowest_kind
              << "), " << kinds.size() << " kinds\n";
  }
};

// Records the host's answer to a burst, failing the test when it is not a refusal (the first
// few failures are reported; the counts say the rest).
void judge(const Hostile& h, const Answer& a, Tally& t) {
  t.messages += h.messages;
  ++t.kinds[h.kind];
  if (a.seconds > t.slowest) {
    t.slowest = a.seconds;
    t.slowest_kind = h.kind;
  }
  switch (a.kind) {
    case Kind::Refused:
      ++t.refused;
      break;
    case Kind::Closed:
      ++t.closed;
      break;
    case Kind::Timeout:
      ++t.unanswered;
      break;
  }
  const bool unanswered = a.kind == Kind::Timeout;
  const bool unnamed = !h.reason_has.empty() && (a.kind != Kind::Refused ||
                                                 a.reason.find(h.reason_has) == std::string::npos);
  const bool unhealed = h.expect_state && !a.heard_type("state");
  const bool left_open = a.kind == Kind::Refused && !a.closed_after_refusal;
  if ((unanswered || unnamed || unhealed || left_open) && t.reported++ < 10) {
    std::string heard;
    for (const auto& m : a.heard) heard += m + " ";
    ADD_FAILURE() << h.kind << ": "
                  << (unanswered ? "neither refused nor closed within the bound"
                      : unnamed  ? "not refused by name (\"" + h.reason_has + "\")"
                      : unhealed ? "no state before the refusal"
                                 : "refused but left connected")
                  << "; reason \"" << a.reason << "\", heard: " << heard;
  }
  t.failed += unanswered || unnamed || unhealed || left_open;
}

// Sends the burst on a connected peer and judges the answer.
void attack(RawPeer& peer, const Hostile& h, Tally& t) {
  peer.sendRaw(h.bytes, kAnswerBound);
  judge(h, peer.awaitRefusal(kAnswerBound, h.keep_alive), t);
  EXPECT_FALSE(peer.badFrames()) << h.kind << ": the host sent something that is not a message";
}

// A first message no host may take: broken streams, text that is no message, bad hellos,
// messages before the hello, a hello with more behind it, floods, and (rarely) silence.
Hostile firstHostile(Rng& rng, int& slow_left) {
  const int r = uniform(rng, 0, 99);
  if (r < 22) return brokenStream(rng);
  if (r < 44) {
    Hostile h;
    h.kind = "not a message";
    h.bytes = framedText(notAMessage(rng));
    return h;
  }
  if (r < 62) return badHello(rng);
  if (r < 78) {
    Hostile h;
    h.kind = "a message before the hello";
    h.bytes = framedText(notAHello(rng).dump());
    return h;
  }
  if (r < 86) {
    // Refused as messages before the welcome; if the host read them apart it would welcome
    // the hello and refuse the turn in the game instead: refused either way.
    Hostile h;
    h.kind = "a hello with a turn behind it";
    h.bytes = framedText(goodHello().dump()) + framedText(brokenTurnMessage(rng, 0).dump());
    h.messages = 2;
    return h;
  }
  if (r < 95 || slow_left <= 0)
    return flood(rng, hostLimits().messages_per_second, {{"type", "ping"}});
  --slow_left;
  Hostile h;
  h.keep_alive = false;
  if (uniform(rng, 0, 1)) {
    h.kind = "truncated frame";
    const std::string whole = framedText(goodHello().dump());
    h.bytes = whole.substr(0, uniform(rng, 1, static_cast<int>(whole.size()) - 1));
  } else {
    h.kind = "silence";
    h.messages = 0;
  }
  return h;
}

// What a seated peer knows of the rack from the handshake.
struct Seated {
  std::size_t turns = 0;  // turns played so far
  std::string last_hash;  // the host's hash of the last one
  json welcome;
};

// Says a good hello and reads the welcome and the host's hash of the last turn (after the
// host's first turn when the rack has none yet).
std::optional<Seated> takeSeat(RawPeer& peer, const std::string& name,
                               const std::string& token = "") {
  if (!peer.send(goodHello(name, token))) return std::nullopt;
  Seated s;
  bool welcomed = false;
  const double deadline = now() + 4 * kAnswerBound;
  while (now() < deadline) {
    const json m = peer.next(deadline - now());
    if (m.is_null()) return std::nullopt;
    const std::string type = m.value("type", "");
    if (type == "welcome") {
      welcomed = true;
      s.turns = m["turns"].size();
      s.welcome = m;
    } else if (type == "turn" && welcomed) {
      s.turns = m["index"].get<std::size_t>() + 1;
    } else if (type == "hash" && welcomed && s.turns > 0 &&
               m["index"].get<std::size_t>() + 1 == s.turns) {
      s.last_hash = m["hash"].get<std::string>();
      return s;
    } else if (type == "refuse") {
      ADD_FAILURE() << "a good hello was refused: " << m.dump();
      return std::nullopt;
    }
  }
  return std::nullopt;
}

std::string otherHash(const std::string& hash) {
  std::string h = hash;
  h[0] = h[0] == '0' ? '1' : '0';
  return h;
}

// A burst from the seated peer. `echo_safe`: after the host's last turn it is the joiner's
// move, so agreeing the hash first leaves the host waiting for a turn (never one it could play).
Hostile inGameHostile(Rng& rng, const Seated& s, bool echo_safe, const json& a_state,
                      int& slow_left) {
  const json echo = {{"type", "hash"}, {"index", s.turns - 1}, {"hash", s.last_hash}};
  Hostile h;
  const int r = uniform(rng, 0, 99);
  if (r < 12) return brokenStream(rng);
  if (r < 24) {
    h.kind = "in game: not a message";
    h.bytes = framedText(notAMessage(rng));
  } else if (r < 36) {
    h.kind = "in game: a turn while the hash is due";
    const json turn = uniform(rng, 0, 1) ? brokenTurnMessage(rng, s.turns)
                                         : json{{"type", "turn"},
                                                {"index", s.turns},
                                                {"turn", plausibleTurn(rng)},
                                                {"player", "human"}};
    h.bytes = framedText(turn.dump());
  } else if (r < 44) {
    h.kind = "in game: a hash of a turn not played";
    const int index = uniform(rng, 0, 1) ? uniform(rng, static_cast<int>(s.turns), 500)
                                         : uniform(rng, 0, static_cast<int>(s.turns) - 1) - 1;
    h.bytes = framedText(json{{"type", "hash"}, {"index", index}, {"hash", s.last_hash}}.dump());
  } else if (r < 50) {
    h.kind = "in game: a hash that is not hex";
    static const std::vector<std::string> bad = {
        "", "0", "0123456789ABCDEF", "xyz", "0123456789abcdef0", "-123456789abcdef"};
    h.bytes = framedText(
        json{{"type", "hash"}, {"index", s.turns - 1}, {"hash", bad[uniform(rng, 0, 5)]}}.dump());
  } else if (r < 56) {
    h.kind = "in game: a state from the joiner";
    h.bytes =
        framedText(json{{"type", "state"}, {"index", s.turns - 1}, {"state", a_state}}.dump());
  } else if (r < 60) {
    h.kind = "in game: a second hello";
    h.bytes = framedText(goodHello().dump());
  } else if (r < 65) {
    h.kind = "in game: an aim out of range";
    json aim = {{"type", "aim"}, {"heading_rad", 0.5},   {"speed", 1.0},
                {"tip", {0, 0}}, {"elevation_rad", 0.0}, {"cue", nullptr}};
    static const std::vector<std::pair<const char*, json>> bad = {
        {"speed", 25.0},        {"heading_rad", 9.0}, {"tip", {3, 0}},
        {"elevation_rad", 2.0}, {"cue", {9.0, 0.0}},  {"speed", "fast"}};
    const auto& [key, value] = bad[uniform(rng, 0, 5)];
    aim[key] = value;
    h.bytes = framedText(aim.dump());
  } else if (r < 71) {
    h = flood(rng, hostLimits().messages_per_second,
              {{"type", "aim"},
               {"heading_rad", 0.5},
               {"speed", 1.0},
               {"tip", {0, 0}},
               {"elevation_rad", 0.0},
               {"cue", nullptr}});
    h.kind = "in game: a flood of aims";
  } else if (r < 85 && echo_safe) {
    // The hash agreed, then a turn the host must refuse: of another index, broken, or a
    // second hash.
    h.messages = 2;
    const int what = uniform(rng, 0, 2);
    json bad;
    if (what == 0) {
      h.kind = "after the hash: a turn of another index";
      const int index = uniform(rng, 0, 1) ? uniform(rng, static_cast<int>(s.turns) + 1, 500)
                                           : static_cast<int>(s.turns) - 1;
      bad = {{"type", "turn"}, {"index", index}, {"turn", plausibleTurn(rng)}, {"player", "human"}};
    } else if (what == 1) {
      h.kind = "after the hash: a turn out of range";
      bad = brokenTurnMessage(rng, s.turns);
    } else {
      h.kind = "after the hash: a second hash";
      bad = echo;
    }
    h.bytes = framedText(echo.dump()) + framedText(bad.dump());
  } else if (r < 96 || slow_left <= 0) {
    // A wrong hash is healed (the host sends its state), not refused; a broken turn behind it
    // is refused after the state. Text that is no message behind it breaks the link as it is
    // read, before the hash is looked at: closed, no state.
    const json wrong = {{"type", "hash"}, {"index", s.turns - 1}, {"hash", otherHash(s.last_hash)}};
    h.messages = 2;
    if (uniform(rng, 0, 1)) {
      h.kind = "after a wrong hash: a broken turn";
      h.expect_state = true;
      h.bytes = framedText(wrong.dump()) + framedText(brokenTurnMessage(rng, s.turns).dump());
    } else {
      h.kind = "after a wrong hash: not a message";
      h.bytes = framedText(wrong.dump()) + framedText(notAMessage(rng));
    }
  } else {
    --slow_left;
    h.kind = "in game: truncated frame";
    h.keep_alive = false;
    const std::string whole = framedText(echo.dump());
    h.bytes = whole.substr(0, uniform(rng, 1, static_cast<int>(whole.size()) - 1));
  }
  return h;
}

// Whether it is the joiner's move after the turns the welcome carried: replays them.
bool joinerToMove(const json& welcome_json) {
  std::string why;
  const auto m = readMessage(welcome_json, why);
  if (!m || !std::holds_alternative<Welcome>(*m)) return false;
  const Welcome& w = std::get<Welcome>(*m);
  const auto setup = setupOf(w, why);
  if (!setup) return false;
  Match match(*setup);
  for (const WireTurn& t : w.turns) {
    const auto input = parseWireTurn(t, *setup, why);
    if (!input) return false;
    match.play(*input);
  }
  return !match.rack().over() && match.rack().shooter() == rules::Player::B;
}

// Whether the campaign goes on: the host is still up, and not failing again and again.
bool goOn(const RackThread& host, int failures) {
  if (host.finished()) {
    ADD_FAILURE() << "the host's rack ended during the campaign";
    return false;
  }
  return failures < kMostFailures;
}

class ProtocolFuzz : public ::testing::Test {
 protected:
  void SetUp() override { setLogLevel("off"); }  // thousands of refusals, each a warning
  void TearDown() override { setLogLevel("warn"); }
};

TEST_F(ProtocolFuzz, AHostRefusesEveryHostileMessageAndThenPlaysARackInStep) {
  const double start = now();
  const unsigned short port = freePort();
  ASSERT_NE(port, 0);
  const std::string host_text = R"({"seed": 5, "players": {"A": "ai:beginner"}})";
  OnlineRackOptions host;
  host.side = Side::Host;
  host.address = {"127.0.0.1", port};
  host.script = scriptOf(host_text);
  host.match = matchPart(json::parse(host_text));
  host.name = "Host";
  host.wait_s = 4 * kRackBound;
  host.rejoin_s = 4 * kRackBound;
  host.limits = hostLimits();
  host.code = kCode;
  // The campaign drops and rejoins the seat hundreds of times, many of them healed: the
  // per-rack limits are lifted here (AttackTest holds the host to them).
  host.most_heals = 1 << 20;
  host.most_rejoins = 1 << 20;
  // Its wrong codes all come from loopback: not slowed down here (AttackTest checks that).
  host.gate.free_wrong_guesses = 1 << 20;
  RackThread host_rack(host);

  Rng rng(kFuzzSeed);
  int slow_left = kMostSlowBursts;

  // Wait for the host to listen (bounded).
  Tally before;
  {
    RawPeer probe;
    const double deadline = now() + kAnswerBound;
    while (!probe.connect(port, 1.0) && now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_FALSE(host_rack.finished()) << "the host stopped before the campaign";
    ++before.connections;
    attack(probe, brokenStream(rng), before);
  }

  // 1. Before any hello: every connection's first words are hostile.
  for (int i = 0; i < kConnectionsBeforeHello && goOn(host_rack, before.failed); ++i) {
    RawPeer peer;
    if (!peer.connect(port, kAnswerBound)) {
      ADD_FAILURE() << "the host stopped accepting after " << i << " connections";
      break;
    }
    ++before.connections;
    attack(peer, firstHostile(rng, slow_left), before);
  }
  before.print("before the hello");

  // 2. After a good hello: the seat is taken, then the peer misbehaves in the game. The first
  // seat sees the host's break; the others rejoin the rack as it stands.
  Tally after;
  const json a_state = io::snapshotToJson(Match(host.script.setup).snapshot());
  std::optional<bool> echo_safe;
  std::string seat_token;  // the first welcome's: every later seat is a rejoin with it
  for (int i = 0; i < kConnectionsAfterHello && goOn(host_rack, before.failed + after.failed);
       ++i) {
    RawPeer peer;
    if (!peer.connect(port, kAnswerBound)) {
      ADD_FAILURE() << "the host stopped accepting after " << i << " seated connections";
      break;
    }
    ++after.connections;
    const auto seated = takeSeat(peer, "Fuzz" + std::to_string(i), seat_token);
    if (seated && seat_token.empty()) seat_token = seated->welcome.value("token", "");
    if (!seated) {
      ADD_FAILURE() << "connection " << i << ": no welcome and hash for a good hello";
      break;
    }
    if (!echo_safe && seated->welcome["turns"].size() == seated->turns) {
      echo_safe = joinerToMove(seated->welcome);
      std::cout << "[fuzz] after the host's " << seated->turns << " turn(s) the joiner is "
                << (*echo_safe ? "" : "not ") << "to move\n";
    }
    attack(peer, inGameHostile(rng, *seated, echo_safe.value_or(false), a_state, slow_left), after);
  }
  after.print("after a good hello");

  // 3. Intruders while a player holds the seat: refused, and the seated player plays on.
  Tally intruders;
  {
    RawPeer seated_peer;
    ASSERT_TRUE(seated_peer.connect(port, kAnswerBound));
    const auto seated = takeSeat(seated_peer, "Seated", seat_token);
    ASSERT_TRUE(seated.has_value()) << "no seat after the campaign";
    for (int i = 0;
         i < kIntruders && goOn(host_rack, before.failed + after.failed + intruders.failed); ++i) {
      seated_peer.keepAlive();
      RawPeer intruder;
      if (!intruder.connect(port, kAnswerBound)) {
        ADD_FAILURE() << "the host stopped accepting intruders after " << i;
        break;
      }
      ++intruders.connections;
      Hostile h = firstHostile(rng, slow_left);
      if (h.kind == "a hello with a turn behind it") h = badHello(rng);  // a hello would seat it
      attack(intruder, h, intruders);
      seated_peer.keepAlive();
      seated_peer.poll();
      ASSERT_FALSE(seated_peer.closed()) << "the seated player lost the seat to " << h.kind;
    }
    // Still seated: a broken turn of its own is refused by name, in the game.
    const Hostile own = [&] {
      Hostile h;
      h.kind = "the seated player's own bad turn";
      h.bytes = framedText(brokenTurnMessage(rng, seated->turns).dump());
      h.reason_has = "disconnected: you sent";
      return h;
    }();
    attack(seated_peer, own, intruders);
  }
  intruders.print("intruders while seated");

  // 4. A legitimate joiner plays the rack out in step with the host.
  ASSERT_FALSE(host_rack.finished()) << "the host's rack ended during the campaign";
  OnlineRackOptions joiner;
  joiner.side = Side::Joiner;
  joiner.address = {"127.0.0.1", port};
  joiner.script = scriptOf(R"({"players": {"B": "ai:beginner"}})");
  joiner.name = "Joiner";
  joiner.code = kCode;
  joiner.seat_token = seat_token;
  joiner.wait_s = kRackBound;
  joiner.rejoin_s = kRackBound;
  joiner.limits.ping_s = 0.05;  // under the host's silence limit
  RackThread joiner_rack(joiner);
  const auto joined = joiner_rack.result(kRackBound);
  const auto hosted = host_rack.result(kRackBound);
  ASSERT_TRUE(joined.has_value()) << "the joiner's rack did not end within " << kRackBound << " s";
  ASSERT_TRUE(hosted.has_value()) << "the host's rack did not end within " << kRackBound << " s";
  EXPECT_EQ(hosted->outcome, OnlineRackResult::Outcome::InStep) << hosted->why;
  EXPECT_EQ(joined->outcome, OnlineRackResult::Outcome::InStep) << joined->why;
  ASSERT_TRUE(hosted->doc.contains("hashes"));
  ASSERT_TRUE(joined->doc.contains("hashes"));
  EXPECT_EQ(hosted->doc["hashes"], joined->doc["hashes"]);
  EXPECT_GT(hosted->doc["hashes"].size(), 1u);
  EXPECT_EQ(hosted->doc["winner"], joined->doc["winner"]);

  const Tally* phases[] = {&before, &after, &intruders};
  int connections = 0, messages = 0, refused = 0, closed = 0, unanswered = 0;
  for (const Tally* t : phases) {
    connections += t->connections;
    messages += t->messages;
    refused += t->refused;
    closed += t->closed;
    unanswered += t->unanswered;
  }
  std::cout << "[fuzz] total: " << connections << " connections, " << messages << " messages, "
            << refused << " refused by message, " << closed << " closed, " << unanswered
            << " unanswered; the last rack: " << hosted->doc["hashes"].size() << " turns, "
            << hosted->heals << " heal(s) on the host, " << joined->heals << " on the joiner; "
            << (now() - start) << " s\n";
  EXPECT_EQ(unanswered, 0);
  for (const Tally* t : phases) EXPECT_EQ(t->failed, 0);
  EXPECT_GE(messages, 1000);
}

}  // namespace
}  // namespace nineball::net
