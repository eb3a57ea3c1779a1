// A match's state between turns: snapshot, restore and the hash online play compares after
// every turn. The hash must see every field a heal carries, and a restored match must play on
// as the one it came from, or two peers would agree on states that differ.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "net/racks_in_progress.hpp"
#include "nineball/match.hpp"

namespace nineball {
namespace {

using net_test::everyGame;
using net_test::playTurns;
using net_test::setupOf;
using net_test::turnFor;

TEST(MatchSnapshot, ARestoredMatchHasTheSameHash) {
  for (rules::Game game : everyGame()) {
    Match played(setupOf(game));
    playTurns(played, 3);
    const MatchSnapshot s = played.snapshot();
    Match fresh(setupOf(game));
    EXPECT_NE(snapshotHash(fresh.snapshot()), snapshotHash(s)) << rules::gameName(game);
    fresh.restore(s);
    EXPECT_EQ(snapshotHash(fresh.snapshot()), snapshotHash(s)) << rules::gameName(game);
  }
}

TEST(MatchSnapshot, TwoMatchesRestoredFromOneSnapshotPlayTheSameNextTurns) {
  for (rules::Game game : everyGame()) {
    Match played(setupOf(game));
    playTurns(played, 2);
    ASSERT_FALSE(played.rack().over()) << rules::gameName(game);
    const MatchSnapshot s = played.snapshot();
    // One restored into a fresh match, one into a match that had played other turns.
    Match a(setupOf(game));
    Match b(setupOf(game, 99));
    playTurns(b, 1);
    a.restore(s);
    b.restore(s);
    for (int i = 2; i < 5 && !a.rack().over(); ++i) {
      const TurnInput turn = turnFor(a, i);
      a.play(turn);
      b.play(turn);
      ASSERT_EQ(snapshotHash(a.snapshot()), snapshotHash(b.snapshot()))
          << rules::gameName(game) << " turn " << i;
    }
  }
}

TEST(MatchSnapshot, NoSnapshotOrRestoreWhileAShotRolls) {
  Match m(setupOf(rules::Game::NineBall));
  const MatchSnapshot before = m.snapshot();
  m.beginShot(turnFor(m, 0));
  EXPECT_THROW(m.snapshot(), IllegalAction);
  EXPECT_THROW(m.restore(before), IllegalAction);
}

// Every field of a snapshot changes its hash: a field the hash missed would let two peers
// agree while their states differ.
TEST(MatchSnapshot, TheHashSeesEveryField) {
  Match m(setupOf(rules::Game::Snooker));
  playTurns(m, 2);
  const MatchSnapshot base = m.snapshot();
  ASSERT_FALSE(base.balls_before.empty());
  const std::uint64_t h = snapshotHash(base);
  using Change = std::function<void(MatchSnapshot&)>;
  const std::vector<std::pair<const char*, Change>> changes = {
      {"ball x",
       [](MatchSnapshot& s) { s.balls[1].pos.x = std::nextafter(s.balls[1].pos.x, 9.0); }},
      {"ball vy", [](MatchSnapshot& s) { s.balls[1].vel.y += 1e-300; }},
      {"ball spin", [](MatchSnapshot& s) { s.balls[2].w.z = 1e-300; }},
      {"ball mass", [](MatchSnapshot& s) { s.balls[0].mass = 0.17; }},
      {"ball pocket", [](MatchSnapshot& s) { s.balls[3].pocket = PocketId::BottomSide; }},
      {"racked", [](MatchSnapshot& s) { s.rack.racked.pop_back(); }},
      {"on_table", [](MatchSnapshot& s) { s.rack.on_table.pop_back(); }},
      {"shooter",
       [](MatchSnapshot& s) {
         s.rack.shooter = s.rack.shooter == rules::Player::A ? rules::Player::B : rules::Player::A;
       }},
      {"break_next", [](MatchSnapshot& s) { s.rack.break_next = !s.rack.break_next; }},
      {"ball_in_hand", [](MatchSnapshot& s) { s.rack.ball_in_hand = !s.rack.ball_in_hand; }},
      {"push_out",
       [](MatchSnapshot& s) { s.rack.push_out_available = !s.rack.push_out_available; }},
      {"decision",
       [](MatchSnapshot& s) { s.rack.decision = rules::Decision::PlayPutBackOrReplace; }},
      {"winner", [](MatchSnapshot& s) { s.rack.winner = rules::Player::B; }},
      {"fouls", [](MatchSnapshot& s) { s.rack.fouls[1] += 1; }},
      {"score", [](MatchSnapshot& s) { s.rack.score[0] += 1; }},
      {"group a", [](MatchSnapshot& s) { s.rack.groups.a = rules::Group::Stripes; }},
      {"group b", [](MatchSnapshot& s) { s.rack.groups.b = rules::Group::Solids; }},
      {"target", [](MatchSnapshot& s) { s.rack.target += 1; }},
      {"innings", [](MatchSnapshot& s) { s.rack.innings[1] += 1; }},
      {"inning_open", [](MatchSnapshot& s) { s.rack.inning_open = !s.rack.inning_open; }},
      {"run", [](MatchSnapshot& s) { s.rack.run += 1; }},
      {"high_run", [](MatchSnapshot& s) { s.rack.high_run[1] += 1; }},
      {"equalising", [](MatchSnapshot& s) { s.rack.equalising = !s.rack.equalising; }},
      {"draw", [](MatchSnapshot& s) { s.rack.draw = !s.rack.draw; }},
      {"colour_on", [](MatchSnapshot& s) { s.rack.snooker.colour_on = !s.rack.snooker.colour_on; }},
      {"free_ball", [](MatchSnapshot& s) { s.rack.snooker.free_ball = !s.rack.snooker.free_ball; }},
      {"respotted_black",
       [](MatchSnapshot& s) { s.rack.snooker.respotted_black = !s.rack.snooker.respotted_black; }},
      {"misses", [](MatchSnapshot& s) { s.rack.snooker.misses[0] += 1; }},
      {"colour_on_before",
       [](MatchSnapshot& s) {
         s.rack.snooker.colour_on_before = !s.rack.snooker.colour_on_before;
       }},
      {"free_ball_before",
       [](MatchSnapshot& s) {
         s.rack.snooker.free_ball_before = !s.rack.snooker.free_ball_before;
       }},
      {"on_table_before", [](MatchSnapshot& s) { s.rack.snooker.on_table_before.push_back(99); }},
      {"cue_pocketed", [](MatchSnapshot& s) { s.cue_pocketed = !s.cue_pocketed; }},
      {"balls_before", [](MatchSnapshot& s) { s.balls_before[4].pos.y += 1e-12; }},
  };
  for (const auto& [name, change] : changes) {
    MatchSnapshot s = base;
    change(s);
    EXPECT_NE(snapshotHash(s), h) << name;
  }
}

}  // namespace
}  // namespace nineball
