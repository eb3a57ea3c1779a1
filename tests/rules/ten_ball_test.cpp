// Every ten-ball rule of issue 15, fed with hand-made shot summaries.
#include <gtest/gtest.h>

#include <stdexcept>

#include "nineball/rules.hpp"

using nineball::PocketId;
using nineball::rules::Call;
using nineball::rules::Decision;
using nineball::rules::Foul;
using nineball::rules::Game;
using nineball::rules::Player;
using nineball::rules::Rack;
using nineball::rules::RuleSet;
using nineball::rules::ShotSummary;

namespace {

const std::vector<int> kTenBalls{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};

// Every ball in a shot drops in the top-left pocket unless told otherwise.
ShotSummary tenHit(int first, std::vector<int> pocketed = {}, bool rail = true) {
  ShotSummary s;
  s.first_contact = first;
  s.pockets.assign(pocketed.size(), PocketId::TopLeft);
  s.pocketed = std::move(pocketed);
  s.rail_after_contact = rail;
  return s;
}

ShotSummary tenCalled(ShotSummary s, int ball, PocketId pocket = PocketId::TopLeft) {
  s.call = Call{ball, pocket};
  return s;
}

ShotSummary tenBreak(int first, std::vector<int> pocketed, int to_rail) {
  ShotSummary s = tenHit(first, std::move(pocketed));
  s.object_balls_to_rail = to_rail;
  return s;
}

Rack tenRacked() {
  return Rack(Game::TenBall, RuleSet::Wpa, kTenBalls);
}

Rack tenAfterBreak(std::vector<int> balls) {
  return Rack(Game::TenBall, RuleSet::Wpa, std::move(balls), false);
}

}  // namespace

TEST(TenBallRules, NameAndBook) {
  EXPECT_STREQ(gameName(Game::TenBall), "ten-ball");
  EXPECT_EQ(nineball::rules::gameFromName("ten-ball"), Game::TenBall);
  EXPECT_FALSE(nineball::rules::gameFromName("crokinole"));
  EXPECT_THROW(Rack(Game::TenBall, RuleSet::Paper, kTenBalls), std::invalid_argument);
}

TEST(TenBallRules, BreakNeedsTheOneFirstAndAPotOrFourToRail) {
  {
    Rack rack = tenRacked();
    EXPECT_FALSE(rack.callRequired());  // the break is not called
    const auto v = rack.shoot(tenBreak(1, {}, 4));
    EXPECT_TRUE(v.legal());
    EXPECT_EQ(v.next, Player::B);
  }
  {
    Rack rack = tenRacked();
    const auto v = rack.shoot(tenBreak(1, {}, 3));
    EXPECT_EQ(v.foul, Foul::BadBreak);
    EXPECT_TRUE(v.ball_in_hand);
  }
  {
    Rack rack = tenRacked();
    EXPECT_EQ(rack.shoot(tenBreak(2, {5}, 6)).foul, Foul::BadBreak);
  }
  {
    Rack rack = tenRacked();
    const auto v = rack.shoot(tenBreak(1, {5}, 0));  // an uncalled pot counts on the break
    EXPECT_TRUE(v.legal());
    EXPECT_EQ(v.next, Player::A);
    EXPECT_FALSE(v.awaiting_decision);
  }
}

TEST(TenBallRules, TenOnTheBreakIsSpotted) {
  Rack rack = tenRacked();
  const auto v = rack.shoot(tenBreak(1, {10, 3}, 2));
  EXPECT_TRUE(v.legal());
  EXPECT_FALSE(v.winner);
  EXPECT_EQ(v.to_spot, std::vector<int>{10});
  EXPECT_EQ(v.next, Player::A);
  const auto& on = rack.ballsOnTable();
  EXPECT_NE(std::find(on.begin(), on.end(), 10), on.end());
}

TEST(TenBallRules, EveryShotAfterTheBreakIsCalled) {
  Rack rack = tenRacked();
  rack.shoot(tenBreak(1, {2}, 0));
  EXPECT_TRUE(rack.callRequired());
  const auto v = rack.shoot(tenCalled(tenHit(1, {1}), 1));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.call_breach, Foul::None);
  EXPECT_EQ(v.next, Player::A);
  EXPECT_TRUE(rack.callRequired());
}

TEST(TenBallRules, CalledBallInAnotherPocketEndsTheTurnOpponentChooses) {
  for (bool shoot : {true, false}) {
    Rack rack = tenAfterBreak(kTenBalls);
    const auto v = rack.shoot(tenCalled(tenHit(1, {1}), 1, PocketId::BottomRight));
    EXPECT_TRUE(v.legal());
    EXPECT_EQ(v.call_breach, Foul::WrongPocket);
    EXPECT_FALSE(v.ball_in_hand);
    EXPECT_EQ(v.decision, Decision::PlayOrPass);
    EXPECT_EQ(v.next, Player::B);
    EXPECT_EQ(rack.ballOn(), 2);  // the 1 stays down
    EXPECT_THROW(rack.shoot(tenCalled(tenHit(2), 2)), std::logic_error);
    rack.decide(shoot);
    EXPECT_EQ(rack.shooter(), shoot ? Player::B : Player::A);
  }
}

TEST(TenBallRules, UncalledPotEndsTheTurnOpponentChooses) {
  Rack rack = tenAfterBreak(kTenBalls);
  const auto v = rack.shoot(tenCalled(tenHit(1, {4}), 1));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.call_breach, Foul::NoCall);
  EXPECT_EQ(v.decision, Decision::PlayOrPass);
  EXPECT_EQ(v.next, Player::B);
}

TEST(TenBallRules, CalledBallMadeOtherBallsCountToo) {
  Rack rack = tenAfterBreak(kTenBalls);
  const auto v = rack.shoot(tenCalled(tenHit(1, {4, 1}), 1));
  EXPECT_EQ(v.call_breach, Foul::None);
  EXPECT_EQ(v.next, Player::A);
  EXPECT_EQ(rack.ballOn(), 2);
}

TEST(TenBallRules, AMissWithNothingDownIsAnOrdinaryTurnEnd) {
  Rack rack = tenAfterBreak(kTenBalls);
  const auto v = rack.shoot(tenCalled(tenHit(1), 1));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.call_breach, Foul::None);
  EXPECT_FALSE(v.awaiting_decision);
  EXPECT_EQ(v.next, Player::B);
}

TEST(TenBallRules, TenEarlyOnACalledShotWins) {
  Rack rack = tenAfterBreak(kTenBalls);
  const auto v = rack.shoot(tenCalled(tenHit(1, {10}), 10));
  EXPECT_TRUE(v.legal());
  ASSERT_TRUE(v.winner);
  EXPECT_EQ(*v.winner, Player::A);
}

TEST(TenBallRules, TenEarlyUncalledIsSpottedAndTheTurnEnds) {
  Rack rack = tenAfterBreak(kTenBalls);
  const auto v = rack.shoot(tenCalled(tenHit(1, {10}), 3));
  EXPECT_FALSE(v.winner);
  EXPECT_EQ(v.call_breach, Foul::NoCall);
  EXPECT_EQ(v.to_spot, std::vector<int>{10});
  EXPECT_EQ(v.decision, Decision::PlayOrPass);
}

TEST(TenBallRules, TenInTheWrongPocketIsSpotted) {
  Rack rack = tenAfterBreak({1, 10});
  const auto v = rack.shoot(tenCalled(tenHit(1, {10}), 10, PocketId::TopSide));
  EXPECT_FALSE(v.winner);
  EXPECT_EQ(v.call_breach, Foul::WrongPocket);
  EXPECT_EQ(v.to_spot, std::vector<int>{10});
}

TEST(TenBallRules, TenWithTheCalledBallIsSpottedTheShooterContinues) {
  Rack rack = tenAfterBreak(kTenBalls);
  const auto v = rack.shoot(tenCalled(tenHit(1, {1, 10}), 1));
  EXPECT_FALSE(v.winner);
  EXPECT_EQ(v.to_spot, std::vector<int>{10});
  EXPECT_EQ(v.next, Player::A);
}

TEST(TenBallRules, TenOnAFoulIsSpotted) {
  Rack rack = tenAfterBreak(kTenBalls);
  const auto v = rack.shoot(tenCalled(tenHit(3, {10}), 10));
  EXPECT_EQ(v.foul, Foul::WrongBallFirst);
  EXPECT_EQ(v.call_breach, Foul::None);  // a foul, not a call question
  EXPECT_EQ(v.to_spot, std::vector<int>{10});
  EXPECT_TRUE(v.ball_in_hand);
}

TEST(TenBallRules, PushOutAfterTheBreakNeedsNoCall) {
  for (bool shoot : {true, false}) {
    Rack rack = tenRacked();
    rack.shoot(tenBreak(1, {}, 5));
    EXPECT_TRUE(rack.pushOutAvailable());
    ShotSummary push;
    push.pocketed = {10};
    push.pockets = {PocketId::TopLeft};
    const auto v = rack.shoot(push, true);
    EXPECT_TRUE(v.legal());
    EXPECT_EQ(v.decision, Decision::PlayOrPass);
    EXPECT_EQ(v.to_spot, std::vector<int>{10});
    EXPECT_EQ(v.call_breach, Foul::None);
    rack.decide(shoot);
    EXPECT_EQ(rack.shooter(), shoot ? Player::A : Player::B);
    EXPECT_FALSE(rack.pushOutAvailable());
    EXPECT_THROW(rack.shoot(tenCalled(tenHit(1), 1), true), std::logic_error);
  }
}

TEST(TenBallRules, ThreeFoulsInARowLose) {
  Rack rack = tenAfterBreak(kTenBalls);
  ShotSummary miss;
  rack.shoot(miss);                     // A foul 1
  rack.shoot(tenCalled(tenHit(1), 1));  // B
  rack.shoot(miss);                     // A foul 2
  rack.shoot(tenCalled(tenHit(1), 1));  // B
  EXPECT_EQ(rack.consecutiveFouls(Player::A), 2);
  const auto v = rack.shoot(miss);  // A foul 3
  EXPECT_EQ(v.foul, Foul::ThreeFouls);
  EXPECT_EQ(v.winner, Player::B);
}

TEST(TenBallRules, ATurnEndedByTheCallIsNoFoulAndClearsTheCount) {
  Rack rack = tenAfterBreak(kTenBalls);
  ShotSummary miss;
  rack.shoot(miss);  // A foul 1
  rack.shoot(tenCalled(tenHit(1), 1));
  rack.shoot(tenCalled(tenHit(1, {5}), 1));  // A: legal, but not as called
  EXPECT_EQ(rack.consecutiveFouls(Player::A), 0);
}
