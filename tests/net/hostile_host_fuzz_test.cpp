// The protocol fuzz turned around: a fake host (the test) answers a REAL joiner
// (net::playOnlineRack in a thread) with seeded hostile words: broken streams, text that is no
// message, welcomes broken field by field, with turns that do not replay or no seat token,
// refusals full of escape sequences, and hostile messages once the rack is on (turns out of
// range, states not asked for, a bye that claims the rack is played). Every round the joiner
// must end within a bound, never with an exception, its reason free of control characters,
// and everything it sent must be framed messages.
#include <gtest/gtest.h>

#include <iostream>
#include <map>

#include "common/log.hpp"
#include "io/snapshot_json.hpp"
#include "net/attack_support.hpp"

namespace nineball::net {
namespace {

using namespace net_test;

// As many under the sanitizers: fewer seeded rounds draw fewer of the kinds the test requires.
constexpr int kRounds = 40;
constexpr std::uint64_t kSeed = 0x405717e;

const char* kMatch = R"({"seed": 5, "turns": []})";

json aWelcome() {
  const io::MatchScript script = scriptOf(kMatch);
  const Lockstep lockstep(Side::Host, script.setup);
  return toJson(
      welcomeFrom("Mallory", matchPart(json::parse(kMatch)), Race{}, lockstep, makeSeatToken()));
}

json junk(Rng& rng) {
  switch (uniform(rng, 0, 6)) {
    case 0:
      return nullptr;
    case 1:
      return -1;
    case 2:
      return std::string(uniform(rng, 201, 3000), 'w');
    case 3:
      return json::array({json::array({json::array()})});
    case 4:
      return json::object();
    case 5:
      return 1e308;
    default:
      return "\x1b[2J\r\nnineball online: forged";
  }
}

// What the fake host says first, and a name for the tally.
std::pair<std::string, std::string> hostileAnswer(Rng& rng) {
  const int r = uniform(rng, 0, 99);
  if (r < 15) return {"broken stream", brokenStream(rng).bytes};
  if (r < 30) return {"not a message", framedText(notAMessage(rng))};
  if (r < 50) {
    json w = aWelcome();
    static const char* keys[] = {"protocol", "build", "name",   "match",
                                 "race",     "turns", "hashes", "token"};
    const char* key = keys[uniform(rng, 0, 7)];
    if (uniform(rng, 0, 4) == 0) {
      w.erase(key);
    } else {
      w[key] = junk(rng);
    }
    return {std::string("welcome, broken ") + key, framedText(w.dump())};
  }
  if (r < 62) {
    json w = aWelcome();
    const int n = uniform(rng, 1, 5);
    for (int i = 0; i < n; ++i) {
      w["turns"].push_back({{"turn", plausibleTurn(rng)}, {"player", "human"}});
      w["hashes"].push_back("0123456789abcdef");
    }
    if (uniform(rng, 0, 1)) w["turns"][0]["turn"]["speed"] = 99.0;
    return {"welcome, turns that do not replay", framedText(w.dump())};
  }
  if (r < 72) {
    const std::string reason = uniform(rng, 0, 1) ? std::string(uniform(rng, 1, 400), 'r')
                                                  : "\x1b]0;owned\x07\r\nnineball online: ok";
    return {"refuse", framedText(json{{"type", "refuse"}, {"reason", reason}}.dump(
                          -1, ' ', false, json::error_handler_t::replace))};
  }
  // A good welcome, then a hostile message in the game.
  const std::string welcome = framedText(aWelcome().dump());
  json next;
  switch (uniform(rng, 0, 4)) {
    case 0:
      next = brokenTurnMessage(rng, 0);
      break;
    case 1:
      next = {{"type", "state"},
              {"index", 0},
              {"state", io::snapshotToJson(Match(scriptOf(kMatch).setup).snapshot())}};
      break;
    case 2:
      next = {{"type", "hash"}, {"index", uniform(rng, 0, 500)}, {"hash", "0123456789abcdef"}};
      break;
    case 3:
      next = {{"type", "turn"}, {"index", 3}, {"turn", plausibleTurn(rng)}, {"player", "human"}};
      break;
    default:
      next = {{"type", "welcome"}};
      break;
  }
  return {"in game: " + next.value("type", std::string("?")), welcome + framedText(next.dump())};
}

class HostileHostFuzz : public ::testing::Test {
 protected:
  void SetUp() override { setLogLevel("off"); }
  void TearDown() override { setLogLevel("warn"); }
};

TEST_F(HostileHostFuzz, ARealJoinerSurvivesEveryHostileHost) {
  Rng rng(kSeed);
  std::map<std::string, int> kinds;
  std::map<OnlineRackResult::Outcome, int> outcomes;
  int heard_refusals = 0;
  const double start = now();
  for (int round = 0; round < kRounds; ++round) {
    const unsigned short port = freePort();
    ASSERT_NE(port, 0);
    const auto [kind, bytes] = hostileAnswer(rng);
    ++kinds[kind];
    OnlineRackOptions o;
    o.side = Side::Joiner;
    o.address = {"127.0.0.1", port};
    o.script = scriptOf(R"({"players": {"B": "ai:beginner"}})");
    o.code = kCode;
    o.wait_s = 0.5;
    o.rejoin_s = 0.5;
    o.connect_s = 0.5;
    std::optional<RackThread> joiner;
    {
      FakeHost fake(port);
      joiner.emplace(o);
      RawPeer link;
      ASSERT_TRUE(fake.acceptInto(link, kAttackBound)) << kind << ": the joiner never connected";
      const json hello = link.next(kAttackBound, false);
      ASSERT_EQ(hello.value("type", ""), "hello") << kind;
      link.sendRaw(bytes, 1.0);
      for (double until = now() + 1.0; now() < until;) {
        const json m = link.next(until - now(), false);
        if (m.is_null()) break;
        heard_refusals += m.value("type", "") == "refuse";
      }
      EXPECT_FALSE(link.badFrames()) << kind << ": the joiner sent what is not a message";
    }  // the fake host goes: the joiner's retries find nobody
    std::optional<OnlineRackResult> r;
    ASSERT_NO_THROW(r = joiner->result(4 * kAttackBound)) << kind;
    ASSERT_TRUE(r.has_value()) << kind << ": the joiner did not end";
    ++outcomes[r->outcome];
    EXPECT_EQ(r->why.find_first_of("\x1b\x07\r\n"), std::string::npos)
        << kind << ": " << json(r->why).dump();
  }
  std::cout << "[hostile host] " << kRounds << " rounds, " << kinds.size() << " kinds, "
            << heard_refusals << " refusals heard from the joiner; outcomes:";
  for (const auto& [outcome, n] : outcomes)
    std::cout << " " << static_cast<int>(outcome) << "x" << n;
  std::cout << "; " << (now() - start) << " s\n";
  EXPECT_GE(kinds.size(), 10u);
}

}  // namespace
}  // namespace nineball::net
