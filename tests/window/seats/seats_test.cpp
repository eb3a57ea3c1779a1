// The seats at the window and the one turn pipeline: a person, the computer and a player at
// another computer each answer whose move it is, who shows the cue and what the status says.
#include "window/seats/seats.hpp"

#include <gtest/gtest.h>

#include "window/game_rolling.hpp"

namespace nineball::window {
namespace {

using ai::Level;

// A player at another computer as the online game lends it, set by hand.
struct FakeRemote : RemoteControl {
  bool holds = false;
  bool aiming = false;
  bool controls(const GameSession&) const override { return holds; }
  bool showsCue() const override { return aiming; }
  double pull() const override { return 0.07; }
  std::string status(const GameSession&) const override { return "Ann is aiming..."; }
};

// Player 1 misses: the turn is Player 2's.
void passTheTurn(GameSession& s) {
  s.setHeading(3.0);
  s.setSpeed(0.3);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  ASSERT_EQ(s.seatToMove(), 1);
}

TEST(Seats, TwoPeopleAtThisComputerPlayEveryTurnThemselves) {
  GameSession s{MatchSetup{}};
  Seats seats(1);
  EXPECT_TRUE(std::holds_alternative<LocalSeat>(seats.seat(0)));
  EXPECT_TRUE(std::holds_alternative<LocalSeat>(seats.seat(1)));
  EXPECT_FALSE(seats.controls(s));
  EXPECT_FALSE(seats.showsCue(s));
  EXPECT_EQ(seats.status(s), s.status());
  passTheTurn(s);
  EXPECT_FALSE(seats.controls(s));
}

TEST(Seats, TheComputerHasTheTableOnlyOnItsOwnMove) {
  GameSession s{MatchSetup{}};
  Seats seats(1);
  seats.setOpponent(s, ComputerSeat{Level::Casual});
  EXPECT_TRUE(std::holds_alternative<LocalSeat>(seats.seat(0)));
  EXPECT_TRUE(std::holds_alternative<PlannerSeat>(seats.seat(1)));
  EXPECT_TRUE(std::holds_alternative<LocalSeat>(seats.mover(s)));  // Player 1 breaks
  EXPECT_FALSE(seats.controls(s));
  passTheTurn(s);
  EXPECT_TRUE(std::holds_alternative<PlannerSeat>(seats.mover(s)));
  EXPECT_TRUE(seats.controls(s));
  EXPECT_EQ(seats.status(s), seats.computer().status(s));
  seats.setOpponent(s, HumanSeat{});
  EXPECT_TRUE(std::holds_alternative<LocalSeat>(seats.seat(1)));
  EXPECT_FALSE(seats.controls(s));
}

TEST(Seats, ARemotePlayerHoldsItsSeatAndTheTableWhileItsLinkIsNotSettled) {
  GameSession s{MatchSetup{}};
  Seats seats(1);
  seats.setOpponent(s, ComputerSeat{Level::Casual});
  FakeRemote remote;
  seats.setRemote(1, remote);
  EXPECT_TRUE(std::holds_alternative<RemoteSeat>(seats.seat(1)));
  EXPECT_FALSE(seats.controls(s));
  remote.holds = true;  // the link not settled: even this side's move waits
  EXPECT_TRUE(std::holds_alternative<RemoteSeat>(seats.mover(s)));
  EXPECT_TRUE(seats.controls(s));
  EXPECT_EQ(seats.status(s), "Ann is aiming...");
  EXPECT_FALSE(seats.showsCue(s));
  remote.aiming = true;
  EXPECT_TRUE(seats.showsCue(s));
  EXPECT_DOUBLE_EQ(seats.pull(s), 0.07);
  seats.clearRemote();
  EXPECT_TRUE(std::holds_alternative<PlannerSeat>(seats.seat(1)));
  EXPECT_FALSE(seats.controls(s));
}

TEST(Seats, AJoinersRemotePlayerSitsInTheFirstSeat) {
  GameSession s{MatchSetup{}};
  Seats seats(1);
  FakeRemote remote;
  seats.setRemote(0, remote);
  EXPECT_TRUE(std::holds_alternative<RemoteSeat>(seats.seat(0)));
  EXPECT_TRUE(std::holds_alternative<LocalSeat>(seats.seat(1)));
  EXPECT_TRUE(std::holds_alternative<RemoteSeat>(seats.mover(s)));
}

}  // namespace
}  // namespace nineball::window
