// Every eight-ball rule of issue 15, fed with hand-made shot summaries.
#include <gtest/gtest.h>

#include <stdexcept>

#include "nineball/rules.hpp"

using nineball::PocketId;
using nineball::rules::Call;
using nineball::rules::Decision;
using nineball::rules::Foul;
using nineball::rules::Game;
using nineball::rules::Group;
using nineball::rules::Player;
using nineball::rules::Rack;
using nineball::rules::RuleSet;
using nineball::rules::ShotSummary;

namespace {

std::vector<int> fullRack() {
  std::vector<int> balls;
  for (int b = 1; b <= 15; ++b) balls.push_back(b);
  return balls;
}

// Every ball in a shot drops in the top-right pocket unless told otherwise.
ShotSummary hit(int first, std::vector<int> pocketed = {}, bool rail = true) {
  ShotSummary s;
  s.first_contact = first;
  s.pockets.assign(pocketed.size(), PocketId::TopRight);
  s.pocketed = std::move(pocketed);
  s.rail_after_contact = rail;
  return s;
}

ShotSummary breakShot(std::vector<int> pocketed, int to_rail) {
  ShotSummary s = hit(1, std::move(pocketed));
  s.object_balls_to_rail = to_rail;
  return s;
}

ShotSummary called(ShotSummary s, int ball, PocketId pocket) {
  s.call = Call{ball, pocket};
  return s;
}

Rack racked() {
  return Rack(Game::EightBall, RuleSet::Wpa, fullRack());
}

// A rack past its break, A to shoot, with `balls` on the table and the table open.
Rack afterBreak(std::vector<int> balls) {
  return Rack(Game::EightBall, RuleSet::Wpa, std::move(balls), false);
}

// A rack where A holds the solids: A potted the 1 and shoots again.
Rack aHoldsSolids(std::vector<int> balls) {
  balls.push_back(1);
  Rack rack = afterBreak(balls);
  rack.shoot(hit(1, {1}));
  return rack;
}

}  // namespace

TEST(EightBallRules, NameAndBook) {
  EXPECT_STREQ(gameName(Game::EightBall), "eight-ball");
  EXPECT_EQ(nineball::rules::gameFromName("eight-ball"), Game::EightBall);
  EXPECT_EQ(racked().game(), Game::EightBall);
  EXPECT_THROW(Rack(Game::EightBall, RuleSet::Paper, fullRack()), std::invalid_argument);
}

TEST(EightBallRules, FoulNamesAreTheIssues) {
  EXPECT_STREQ(foulName(Foul::EightEarly), "eight-early");
  EXPECT_STREQ(foulName(Foul::WrongGroupFirst), "wrong-group-first");
  EXPECT_STREQ(foulName(Foul::WrongPocket), "wrong-pocket");
  EXPECT_STREQ(foulName(Foul::NoCall), "no-call");
  EXPECT_STREQ(groupName(Group::Solids), "solids");
  EXPECT_STREQ(groupName(Group::Stripes), "stripes");
}

TEST(EightBallRules, LegalBreakPotsABall) {
  Rack rack = racked();
  const auto v = rack.shoot(breakShot({3}, 0));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.next, Player::A);
  EXPECT_TRUE(v.groups.open());  // a pot on the break sets no group
  EXPECT_FALSE(rack.isBreak());
}

TEST(EightBallRules, LegalBreakFourToARail) {
  Rack rack = racked();
  const auto v = rack.shoot(breakShot({}, 4));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.next, Player::B);
  EXPECT_FALSE(v.ball_in_hand);
}

TEST(EightBallRules, IllegalBreakOpponentPlaysOn) {
  Rack rack = racked();
  const auto v = rack.shoot(breakShot({}, 3));
  EXPECT_EQ(v.foul, Foul::BadBreak);
  EXPECT_EQ(v.decision, Decision::RerackOrPlayOn);
  EXPECT_TRUE(v.awaiting_decision);
  EXPECT_EQ(v.next, Player::B);
  EXPECT_FALSE(v.ball_in_hand);
  EXPECT_THROW(rack.shoot(hit(1)), std::logic_error);  // the choice comes first
  rack.decide(true);
  EXPECT_EQ(rack.shooter(), Player::B);
  EXPECT_FALSE(rack.isBreak());
  EXPECT_TRUE(rack.shoot(hit(2)).legal());
}

TEST(EightBallRules, IllegalBreakOpponentReracksAndBreaks) {
  Rack rack = racked();
  rack.shoot(breakShot({}, 2));
  rack.decide(false);
  EXPECT_TRUE(rack.isBreak());
  EXPECT_EQ(rack.shooter(), Player::B);
  EXPECT_EQ(rack.ballsOnTable(), fullRack());
  EXPECT_FALSE(rack.awaitingDecision());
  EXPECT_TRUE(rack.shoot(breakShot({5}, 1)).legal());
}

TEST(EightBallRules, IllegalBreakWithAScratchGivesBallInHandOnPlayOn) {
  Rack rack = racked();
  ShotSummary s = breakShot({}, 1);
  s.cue_pocketed = true;
  const auto v = rack.shoot(s);
  EXPECT_EQ(v.decision, Decision::RerackOrPlayOn);
  EXPECT_TRUE(v.ball_in_hand);
}

TEST(EightBallRules, EightOnTheBreakIsSpottedAndTheBreakerContinues) {
  Rack rack = racked();
  const auto v = rack.shoot(breakShot({8, 4}, 0));
  EXPECT_TRUE(v.legal());
  EXPECT_FALSE(v.winner);
  EXPECT_EQ(v.to_spot, std::vector<int>{8});
  EXPECT_EQ(v.next, Player::A);
  const auto& on = rack.ballsOnTable();
  EXPECT_NE(std::find(on.begin(), on.end(), 8), on.end());
  EXPECT_EQ(std::find(on.begin(), on.end(), 4), on.end());
}

TEST(EightBallRules, EightOnTheBreakWithAScratchIsSpottedNotALoss) {
  Rack rack = racked();
  ShotSummary s = breakShot({8}, 0);
  s.cue_pocketed = true;
  const auto v = rack.shoot(s);
  EXPECT_EQ(v.foul, Foul::Scratch);
  EXPECT_FALSE(v.winner);
  EXPECT_EQ(v.to_spot, std::vector<int>{8});
  EXPECT_EQ(v.next, Player::B);
  EXPECT_TRUE(v.ball_in_hand);
  EXPECT_TRUE(rack.groups().open());
}

TEST(EightBallRules, TableOpenAfterTheBreakAnyButTheEightFirst) {
  Rack rack = afterBreak(fullRack());
  EXPECT_TRUE(rack.groups().open());
  EXPECT_EQ(rack.legalFirstBalls().size(), 14u);
  EXPECT_FALSE(rack.callRequired());
  // A stripe first to pot a solid is fine on an open table...
  const auto v = rack.shoot(hit(12, {3}));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.groups.a, Group::Solids);
  EXPECT_EQ(v.groups.b, Group::Stripes);
  EXPECT_EQ(v.next, Player::A);
  // ...but not the 8.
  Rack open = afterBreak(fullRack());
  EXPECT_EQ(open.shoot(hit(8)).foul, Foul::WrongGroupFirst);
}

TEST(EightBallRules, FirstLegalPotSetsTheGroupsForEitherPlayer) {
  Rack rack = afterBreak(fullRack());
  rack.shoot(hit(2));  // A misses: B to shoot, still open
  EXPECT_TRUE(rack.groups().open());
  const auto v = rack.shoot(hit(10, {10}));
  EXPECT_EQ(v.groups.b, Group::Stripes);
  EXPECT_EQ(v.groups.a, Group::Solids);
  EXPECT_EQ(rack.shooter(), Player::B);
}

TEST(EightBallRules, PotsOfBothGroupsTheCallOrTheFirstDecides) {
  {
    Rack rack = afterBreak(fullRack());
    EXPECT_EQ(rack.shoot(hit(3, {11, 3})).groups.a, Group::Stripes);
  }
  {
    Rack rack = afterBreak(fullRack());
    EXPECT_EQ(rack.shoot(called(hit(3, {11, 3}), 3, PocketId::TopRight)).groups.a, Group::Solids);
  }
}

TEST(EightBallRules, AFoulSetsNoGroup) {
  Rack rack = afterBreak(fullRack());
  ShotSummary s = hit(3, {3});
  s.cue_pocketed = true;
  const auto v = rack.shoot(s);
  EXPECT_EQ(v.foul, Foul::Scratch);
  EXPECT_TRUE(v.groups.open());
  EXPECT_TRUE(v.ball_in_hand);
}

TEST(EightBallRules, ShootersGroupMustBeHitFirst) {
  Rack rack = aHoldsSolids({2, 3, 8, 9, 10});
  EXPECT_EQ(rack.legalFirstBalls(), (std::vector<int>{2, 3}));
  const auto v = rack.shoot(hit(9, {2}));
  EXPECT_EQ(v.foul, Foul::WrongGroupFirst);
  EXPECT_EQ(v.next, Player::B);
  EXPECT_TRUE(v.ball_in_hand);
  // B holds the stripes: a stripe first is right for B.
  EXPECT_EQ(rack.legalFirstBalls(), (std::vector<int>{9, 10}));
  EXPECT_TRUE(rack.shoot(hit(9)).legal());
}

TEST(EightBallRules, OnlyOwnGroupPotsKeepTheTurn) {
  Rack rack = aHoldsSolids({2, 3, 8, 9, 10});
  const auto v = rack.shoot(hit(2, {9}));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.next, Player::B);  // the stripe stays down for B
  const auto& on = rack.ballsOnTable();
  EXPECT_EQ(std::find(on.begin(), on.end(), 9), on.end());
}

TEST(EightBallRules, AnyFoulGivesBallInHand) {
  Rack rack = aHoldsSolids({2, 8, 9});
  ShotSummary nothing;
  const auto v = rack.shoot(nothing);
  EXPECT_EQ(v.foul, Foul::NoContact);
  EXPECT_TRUE(v.ball_in_hand);
  EXPECT_EQ(rack.shoot(hit(9, {}, false)).foul, Foul::NoRail);
  EXPECT_TRUE(rack.ballInHand());
}

TEST(EightBallRules, ClearedGroupThenTheEightMustBeHitFirst) {
  Rack rack = aHoldsSolids({2, 8, 9});
  EXPECT_FALSE(rack.callRequired());
  rack.shoot(called(hit(2, {2}), 2, PocketId::TopRight));  // clears the solids
  EXPECT_EQ(rack.legalFirstBalls(), std::vector<int>{8});
  EXPECT_TRUE(rack.callRequired());
  EXPECT_EQ(rack.shooter(), Player::A);
  // The 8 first is right now, a stripe first is not.
  Rack copy = rack;
  EXPECT_TRUE(copy.shoot(called(hit(8), 8, PocketId::TopLeft)).legal());
  EXPECT_EQ(rack.shoot(called(hit(9), 8, PocketId::TopLeft)).foul, Foul::WrongGroupFirst);
}

TEST(EightBallRules, EightInTheCalledPocketWins) {
  Rack rack = aHoldsSolids({8, 9});
  const auto v = rack.shoot(called(hit(8, {8}), 8, PocketId::TopRight));
  EXPECT_TRUE(v.legal());
  ASSERT_TRUE(v.winner);
  EXPECT_EQ(*v.winner, Player::A);
  EXPECT_TRUE(rack.over());
}

TEST(EightBallRules, EightEarlyLoses) {
  Rack rack = aHoldsSolids({2, 8, 9});
  const auto v = rack.shoot(called(hit(2, {8}), 8, PocketId::TopRight));
  EXPECT_EQ(v.foul, Foul::EightEarly);
  ASSERT_TRUE(v.winner);
  EXPECT_EQ(*v.winner, Player::B);
}

TEST(EightBallRules, EightWithTheLastGroupBallIsStillEarly) {
  Rack rack = aHoldsSolids({2, 8, 9});
  const auto v = rack.shoot(called(hit(2, {2, 8}), 8, PocketId::TopRight));
  EXPECT_EQ(v.foul, Foul::EightEarly);
  EXPECT_EQ(v.winner, Player::B);
}

TEST(EightBallRules, EightOnAnOpenTableIsEarly) {
  Rack rack = afterBreak(fullRack());
  EXPECT_EQ(rack.shoot(hit(3, {8})).foul, Foul::EightEarly);
  EXPECT_EQ(rack.winner(), Player::B);
}

TEST(EightBallRules, EightInAnUncalledPocketLoses) {
  Rack rack = aHoldsSolids({8, 9});
  const auto v = rack.shoot(called(hit(8, {8}), 8, PocketId::BottomSide));
  EXPECT_EQ(v.foul, Foul::WrongPocket);
  EXPECT_EQ(v.winner, Player::B);
}

TEST(EightBallRules, EightWithoutACallLoses) {
  Rack rack = aHoldsSolids({8, 9});
  const auto v = rack.shoot(hit(8, {8}));
  EXPECT_EQ(v.foul, Foul::NoCall);
  EXPECT_EQ(v.winner, Player::B);
}

TEST(EightBallRules, EightOnAFoulLoses) {
  Rack rack = aHoldsSolids({8, 9});
  ShotSummary s = called(hit(8, {8}), 8, PocketId::TopRight);
  s.cue_pocketed = true;
  const auto v = rack.shoot(s);
  EXPECT_EQ(v.foul, Foul::Scratch);
  EXPECT_EQ(v.winner, Player::B);
  EXPECT_THROW(rack.shoot(hit(9)), std::logic_error);
}

TEST(EightBallRules, NoPushOutInEightBall) {
  Rack rack = racked();
  const auto v = rack.shoot(breakShot({}, 5));
  EXPECT_FALSE(v.push_out_available);
  EXPECT_THROW(rack.shoot(hit(1), true), std::logic_error);
}

TEST(EightBallRules, ARackCopyIsIndependent) {
  Rack rack = afterBreak(fullRack());
  Rack copy = rack;
  copy.shoot(hit(3, {3}));
  EXPECT_TRUE(rack.groups().open());
  EXPECT_FALSE(copy.groups().open());
}
