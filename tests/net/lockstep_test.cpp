// The lockstep bookkeeping of one rack between a host and a joiner, each with its own Match,
// without sockets: whose turn, which index, how the hashes compare, and the heal.
#include "net/lockstep.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "io/snapshot_json.hpp"
#include "nineball/match.hpp"
#include "support/turn_input.hpp"

namespace nineball::net {
namespace {

// Both sides of one rack: each side's Match and Lockstep.
struct Table {
  MatchSetup setup;
  Match host_match{setup};
  Match joiner_match{setup};
  Lockstep host{Side::Host, setup};
  Lockstep joiner{Side::Joiner, setup};

  Match& matchOf(Side s) { return s == Side::Host ? host_match : joiner_match; }
  Lockstep& stepOf(Side s) { return s == Side::Host ? host : joiner; }
  // The side to move now.
  Side mover() {
    return host_match.rack().shooter() == rules::Player::A ? Side::Host : Side::Joiner;
  }
};

Side other(Side s) {
  return s == Side::Host ? Side::Joiner : Side::Host;
}

// The side to move plays `turn`; the other side checks and plays it. Returns the two hash
// messages (the mover's, the other's), not yet exchanged.
std::pair<HashMessage, HashMessage> playBoth(Table& t, const TurnInput& turn) {
  const Side mover = t.mover();
  Lockstep& local = t.stepOf(mover);
  Lockstep& peer = t.stepOf(other(mover));
  EXPECT_TRUE(local.localToMove(t.matchOf(mover)));
  EXPECT_FALSE(peer.localToMove(t.matchOf(other(mover))));
  TurnMessage message;
  const CheckedTurn mine = local.localTurn(turn, HumanSeat{}, message);
  t.matchOf(mover).play(mine.input);
  const HashMessage local_hash = local.played(message.turn, t.matchOf(mover).snapshot());
  std::string why;
  const auto theirs = peer.peerTurn(message, t.matchOf(other(mover)), why);
  EXPECT_TRUE(theirs.has_value()) << why;
  t.matchOf(other(mover)).play(theirs->input);
  const HashMessage peer_hash = peer.played(message.turn, t.matchOf(other(mover)).snapshot());
  return {local_hash, peer_hash};
}

HashVerdict verdict(Lockstep& l, const HashMessage& h) {
  std::string why;
  const auto v = l.peerHash(h, why);
  EXPECT_TRUE(v.has_value()) << why;
  return v.value_or(HashVerdict::Waiting);
}

TEST(Lockstep, TheHostBreaksAndBothSidesAgreeOnEachTurn) {
  Table t;
  EXPECT_EQ(t.mover(), Side::Host);
  for (double heading : {0.0, 2.0, -1.0}) {
    const Side mover = t.mover();
    const auto [mine, theirs] = playBoth(t, test::strokeTurn(heading, 4.0));
    EXPECT_EQ(mine.hash, theirs.hash);
    EXPECT_EQ(mine.index, theirs.index);
    EXPECT_FALSE(t.host.settled());
    EXPECT_EQ(verdict(t.stepOf(mover), theirs), HashVerdict::Agreed);
    EXPECT_EQ(verdict(t.stepOf(other(mover)), mine), HashVerdict::Agreed);
    EXPECT_TRUE(t.host.settled());
    EXPECT_TRUE(t.joiner.settled());
  }
  EXPECT_EQ(t.host.hashes(), t.joiner.hashes());
  EXPECT_EQ(t.host.turns().size(), 3u);
}

TEST(Lockstep, ATurnOutOfTurnIsRefused) {
  Table t;
  // The host is to break; the joiner sends a turn anyway.
  TurnMessage message;
  t.joiner.localTurn(test::strokeTurn(0.0, 4.0), HumanSeat{}, message);
  std::string why;
  EXPECT_FALSE(t.host.peerTurn(message, t.host_match, why).has_value());
  EXPECT_NE(why.find("out of turn"), std::string::npos) << why;
}

TEST(Lockstep, ATurnOfAnotherIndexIsRefused) {
  Table t;
  TurnMessage message;
  t.host.localTurn(test::strokeTurn(0.0, 4.0), HumanSeat{}, message);
  for (std::size_t index : {1u, 2u, 500u}) {
    message.index = index;
    std::string why;
    EXPECT_FALSE(t.joiner.peerTurn(message, t.joiner_match, why).has_value()) << index;
    EXPECT_NE(why.find("when turn 0 was due"), std::string::npos) << why;
  }
  message.index = 0;
  std::string why;
  EXPECT_TRUE(t.joiner.peerTurn(message, t.joiner_match, why).has_value()) << why;
}

TEST(Lockstep, ATurnBeforeTheLastIsAgreedIsRefused) {
  Table t;
  const auto hashes = playBoth(t, test::strokeTurn(0.0, 4.0));
  (void)hashes;
  const Side mover = t.mover();
  TurnMessage next;
  t.stepOf(mover).localTurn(test::strokeTurn(1.0, 2.0), HumanSeat{}, next);
  std::string why;
  EXPECT_FALSE(t.stepOf(mover).localToMove(t.matchOf(mover)));
  EXPECT_FALSE(t.stepOf(other(mover)).peerTurn(next, t.matchOf(other(mover)), why).has_value());
  EXPECT_NE(why.find("agreed"), std::string::npos) << why;
}

TEST(Lockstep, AHashOfATurnNotPlayedOrASecondHashIsRefused) {
  Table t;
  std::string why;
  EXPECT_FALSE(t.host.peerHash({0, 1}, why).has_value());
  EXPECT_NE(why.find("not the last played"), std::string::npos) << why;
  const auto [mine, theirs] = playBoth(t, test::strokeTurn(0.0, 4.0));
  EXPECT_FALSE(t.host.peerHash({1, theirs.hash}, why).has_value());
  EXPECT_FALSE(t.host.peerHash({500, theirs.hash}, why).has_value());
  const Side mover = Side::Host;
  EXPECT_EQ(verdict(t.stepOf(mover), theirs), HashVerdict::Agreed);
  EXPECT_FALSE(t.host.peerHash(theirs, why).has_value());
  EXPECT_NE(why.find("second hash"), std::string::npos) << why;
  (void)mine;
}

// The joiner's match nudged by a nanometre after turn 0: out of step.
struct OutOfStep {
  Table t;
  HashMessage host_hash;
  HashMessage joiner_hash;
};

void breakOutOfStep(OutOfStep& o) {
  TurnMessage message;
  const CheckedTurn mine = o.t.host.localTurn(test::strokeTurn(0.0, 5.0), HumanSeat{}, message);
  o.t.host_match.play(mine.input);
  o.host_hash = o.t.host.played(message.turn, o.t.host_match.snapshot());
  std::string why;
  const auto theirs = o.t.joiner.peerTurn(message, o.t.joiner_match, why);
  ASSERT_TRUE(theirs.has_value()) << why;
  o.t.joiner_match.play(theirs->input);
  MatchSnapshot nudged = o.t.joiner_match.snapshot();
  nudged.balls.back().pos.x += 1e-9;
  o.t.joiner_match.restore(nudged);
  o.joiner_hash = o.t.joiner.played(message.turn, o.t.joiner_match.snapshot());
  ASSERT_NE(o.host_hash.hash, o.joiner_hash.hash);
}

TEST(Lockstep, AMismatchIsHealedWithTheHostsStateOnBothSides) {
  OutOfStep o;
  breakOutOfStep(o);
  Table& t = o.t;
  EXPECT_EQ(verdict(t.host, o.joiner_hash), HashVerdict::Mismatch);
  EXPECT_EQ(verdict(t.joiner, o.host_hash), HashVerdict::Mismatch);
  // The joiner waits for the state: another hash now breaks the protocol.
  std::string why;
  EXPECT_FALSE(t.joiner.peerHash(o.host_hash, why).has_value());

  const MatchSnapshot own = t.host_match.snapshot();
  const StateMessage state = t.host.healMessage(own);
  t.host_match.restore(own);
  EXPECT_EQ(state.index, 0u);
  // As it travels: through its JSON text.
  const StateMessage arrived{state.index, nlohmann::json::parse(state.state.dump())};
  const auto healed = t.joiner.healState(arrived, t.joiner_match, why);
  ASSERT_TRUE(healed.has_value()) << why;
  t.joiner_match.restore(*healed);
  bool took = false;
  const HashMessage again = t.joiner.healed(*healed, took);
  EXPECT_TRUE(took);
  EXPECT_TRUE(t.joiner.settled());
  EXPECT_EQ(again.hash, o.host_hash.hash);
  EXPECT_EQ(verdict(t.host, again), HashVerdict::Agreed);
  EXPECT_EQ(t.host.heals(), 1);
  EXPECT_EQ(t.joiner.heals(), 1);

  // Healed, both play the next turn to the same state.
  const auto [mine, theirs] = playBoth(t, test::strokeTurn(2.5, 3.0));
  EXPECT_EQ(mine.hash, theirs.hash);
}

TEST(Lockstep, AHealThatDoesNotTakeIsUnhealed) {
  OutOfStep o;
  breakOutOfStep(o);
  Table& t = o.t;
  EXPECT_EQ(verdict(t.host, o.joiner_hash), HashVerdict::Mismatch);
  EXPECT_EQ(verdict(t.joiner, o.host_hash), HashVerdict::Mismatch);
  const StateMessage state = t.host.healMessage(t.host_match.snapshot());
  std::string why;
  auto healed = t.joiner.healState(state, t.joiner_match, why);
  ASSERT_TRUE(healed.has_value()) << why;
  healed->balls.front().pos.y += 1e-9;  // the restore goes wrong on the joiner's side
  t.joiner_match.restore(*healed);
  bool took = true;
  const HashMessage again = t.joiner.healed(*healed, took);
  EXPECT_FALSE(took);
  EXPECT_EQ(verdict(t.host, again), HashVerdict::Unhealed);
}

TEST(Lockstep, AStateNotAskedForOrThatDoesNotFitIsRefused) {
  OutOfStep o;
  breakOutOfStep(o);
  Table& t = o.t;
  const StateMessage state = t.host.healMessage(t.host_match.snapshot());
  std::string why;
  // Before the mismatch is known, the joiner did not ask for it.
  EXPECT_FALSE(t.joiner.healState(state, t.joiner_match, why).has_value());
  EXPECT_NE(why.find("not asked for"), std::string::npos) << why;
  // The host never takes a state.
  EXPECT_EQ(verdict(t.host, o.joiner_hash), HashVerdict::Mismatch);
  EXPECT_FALSE(t.host.healState(state, t.host_match, why).has_value());
  EXPECT_NE(why.find("not asked for"), std::string::npos) << why;

  EXPECT_EQ(verdict(t.joiner, o.host_hash), HashVerdict::Mismatch);
  EXPECT_FALSE(t.joiner.healState({1, state.state}, t.joiner_match, why).has_value());
  EXPECT_NE(why.find("not asked for"), std::string::npos) << why;
  // A state of another game's balls, or with a ball off any table.
  MatchSetup snooker;
  snooker.setGame(rules::Game::Snooker);
  const Match other_game(snooker);
  const StateMessage foreign{0, io::snapshotToJson(other_game.snapshot())};
  EXPECT_FALSE(t.joiner.healState(foreign, t.joiner_match, why).has_value());
  EXPECT_NE(why.find("does not fit"), std::string::npos) << why;
  StateMessage far = state;
  far.state["balls"][0]["x"] = 50.0;
  EXPECT_FALSE(t.joiner.healState(far, t.joiner_match, why).has_value());
  EXPECT_NE(why.find("balls[0].x"), std::string::npos) << why;
  // The good one is still taken.
  EXPECT_TRUE(t.joiner.healState(state, t.joiner_match, why).has_value()) << why;
}

// A host's state is believed only when the rack could be in it (issue 46: a hostile host).
TEST(Lockstep, AHealedStateIsCheckedAsASceneAndAgainstTheRules) {
  OutOfStep o;
  breakOutOfStep(o);
  Table& t = o.t;
  EXPECT_EQ(verdict(t.joiner, o.host_hash), HashVerdict::Mismatch);
  const StateMessage good = t.host.healMessage(t.host_match.snapshot());
  const struct {
    const char* what;
    std::function<void(nlohmann::json&)> tamper;
    const char* why;
  } cases[] = {
      {"cue in hand on the table", [](nlohmann::json& s) { s["cue_pocketed"] = true; },
       "in hand is on the table"},
      {"stacked",
       [](nlohmann::json& s) {
         for (auto& b : s["balls"]) b["x"] = 0.2, b["y"] = 0.0;
       },
       "overlaps"},
      {"off the cloth", [](nlohmann::json& s) { s["balls"][0]["x"] = 2.2; }, "off the table"},
      {"too fast", [](nlohmann::json& s) { s["balls"][1]["vy"] = -20.0; }, "faster than any cue"},
      {"spinning",
       [](nlohmann::json& s) {
         s["balls"][1]["w"] = {0.0, 0.0, 9000.0};
       },
       "spins faster"},
      {"a winner", [](nlohmann::json& s) { s["rack"]["winner"] = "B"; }, "winner"},
      {"a draw", [](nlohmann::json& s) { s["rack"]["draw"] = true; }, "winner"},
      {"fouls",
       [](nlohmann::json& s) {
         s["rack"]["fouls"] = {0, 1000000};
       },
       "fouls"},
      {"score",
       [](nlohmann::json& s) {
         s["rack"]["score"] = {500, 0};
       },
       "score"},
      {"on_table", [](nlohmann::json& s) { s["rack"]["on_table"] = nlohmann::json::array(); },
       "on the table"},
  };
  std::string why;
  for (const auto& c : cases) {
    StateMessage bad{good.index, nlohmann::json::parse(good.state.dump())};
    c.tamper(bad.state);
    EXPECT_FALSE(t.joiner.healState(bad, t.joiner_match, why).has_value()) << c.what;
    EXPECT_NE(why.find(c.why), std::string::npos) << c.what << ": " << why;
  }
  EXPECT_TRUE(t.joiner.healState(good, t.joiner_match, why).has_value()) << why;
}

TEST(Lockstep, ARejoinAsksForTheLastTurnsHashAgain) {
  Table t;
  EXPECT_FALSE(t.host.lastHash().has_value());
  const auto [mine, theirs] = playBoth(t, test::strokeTurn(0.0, 4.0));
  EXPECT_EQ(verdict(t.host, theirs), HashVerdict::Agreed);
  t.host.rejoined();
  EXPECT_FALSE(t.host.settled());
  ASSERT_TRUE(t.host.lastHash().has_value());
  EXPECT_EQ(t.host.lastHash()->hash, mine.hash);
  // A new joiner adopts the host's record (as replayed) and both exchange the last hash.
  Lockstep fresh(Side::Joiner, t.setup);
  fresh.adopt(t.host.turns(), t.host.hashes());
  EXPECT_FALSE(fresh.settled());
  EXPECT_EQ(verdict(fresh, *t.host.lastHash()), HashVerdict::Agreed);
  EXPECT_EQ(verdict(t.host, *fresh.lastHash()), HashVerdict::Agreed);
}

}  // namespace
}  // namespace nineball::net
