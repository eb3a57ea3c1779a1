// The session statistics, fed turn records by hand.
#include "window/session_stats.hpp"

#include <gtest/gtest.h>

namespace nineball::window {
namespace {

using rules::Foul;
using rules::Player;

TurnRecord turn(Player shooter, std::vector<int> pocketed, Foul foul = Foul::None,
                std::optional<Player> winner = std::nullopt) {
  TurnRecord r;
  r.shooter = shooter;
  r.verdict.shooter = shooter;
  r.verdict.pocketed = std::move(pocketed);
  r.verdict.foul = foul;
  r.verdict.winner = winner;
  return r;
}

// Seat 0 is Player A in these racks.
void play(SessionStats& s, const TurnRecord& r, bool was_break = false) {
  s.record(r.shooter == Player::A ? 0 : 1, r, was_break);
}

TEST(SessionStats, CountsPotsFoulsAndBreaks) {
  SessionStats s;
  s.startRack();
  play(s, turn(Player::A, {2, 5}), true);               // break: two down
  play(s, turn(Player::A, {1}));                        // a pot
  play(s, turn(Player::A, {}));                         // a miss
  play(s, turn(Player::B, {3}, Foul::WrongBallFirst));  // a foul: the 3 does not count
  play(s, turn(Player::A, {4, 6}));
  EXPECT_EQ(s.seat(0).pots, 5);
  EXPECT_EQ(s.seat(0).breaks, 1);
  EXPECT_EQ(s.seat(0).break_balls, 2);
  EXPECT_EQ(s.seat(0).fouls, 0);
  EXPECT_EQ(s.seat(1).pots, 0);
  EXPECT_EQ(s.seat(1).fouls, 1);
  EXPECT_EQ(s.seat(1).breaks, 0);
  EXPECT_NE(s.line(0).find("pots 5"), std::string::npos) << s.line(0);
  EXPECT_NE(s.line(0).find("breaks 1 (2 down)"), std::string::npos) << s.line(0);
}

TEST(SessionStats, ABreakAndRunIsARunOut) {
  SessionStats s;
  s.startRack();
  play(s, turn(Player::A, {}), true);
  for (int ball = 1; ball < 9; ++ball) play(s, turn(Player::A, {ball}));
  play(s, turn(Player::A, {9}, Foul::None, Player::A));
  EXPECT_EQ(s.seat(0).run_outs, 1);
  EXPECT_EQ(s.seat(0).racks_won, 1);
  EXPECT_EQ(s.seat(0).pots, 9);
}

TEST(SessionStats, WinningOnASecondVisitIsNoRunOut) {
  SessionStats s;
  s.startRack();
  play(s, turn(Player::A, {1}), true);
  play(s, turn(Player::A, {}));  // misses
  play(s, turn(Player::B, {}));  // misses
  play(s, turn(Player::A, {9}, Foul::None, Player::A));
  EXPECT_EQ(s.seat(0).run_outs, 0);
  EXPECT_EQ(s.seat(0).racks_won, 1);
  // The next rack B breaks dry and A runs out from the first visit: that counts.
  play(s, turn(Player::B, {}), true);
  play(s, turn(Player::A, {1, 2, 3, 4, 5, 6, 7, 8}));
  play(s, turn(Player::A, {9}, Foul::None, Player::A));
  EXPECT_EQ(s.seat(0).run_outs, 1);
  EXPECT_EQ(s.seat(0).racks_won, 2);
  EXPECT_EQ(s.seat(1).breaks, 1);
  EXPECT_EQ(s.seat(1).break_balls, 0);
}

TEST(SessionStats, APushOutDecisionIsNoVisitAndAThirdFoulGivesTheOpponentTheRack) {
  SessionStats s;
  s.startRack();
  play(s, turn(Player::A, {}), true);
  TurnRecord push = turn(Player::B, {});
  push.kind = TurnInput::Kind::PushOut;
  play(s, push);
  TurnRecord pass = turn(Player::A, {});
  pass.kind = TurnInput::Kind::Decision;
  play(s, pass);                                       // A passes it back to B
  play(s, turn(Player::B, {1, 2, 3, 4, 5, 6, 7, 8}));  // B's visit goes on
  play(s, turn(Player::B, {9}, Foul::None, Player::B));
  EXPECT_EQ(s.seat(1).run_outs, 1);
  // A's third foul in a row loses A the rack: B wins it, and no run-out.
  play(s, turn(Player::B, {}), true);
  play(s, turn(Player::A, {}, Foul::NoRail, Player::B));
  EXPECT_EQ(s.seat(1).racks_won, 2);
  EXPECT_EQ(s.seat(1).run_outs, 1);
  EXPECT_EQ(s.seat(0).fouls, 1);
}

}  // namespace
}  // namespace nineball::window
