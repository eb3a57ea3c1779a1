// Every rule of both rule sets, fed with hand-made shot summaries.
#include <gtest/gtest.h>

#include <stdexcept>

#include "nineball/rules.hpp"

using nineball::rules::Foul;
using nineball::rules::Player;
using nineball::rules::Rack;
using nineball::rules::RuleSet;
using nineball::rules::ShotSummary;

namespace {

const std::vector<int> kNineBalls{1, 2, 3, 4, 5, 6, 7, 8, 9};

ShotSummary nineHit(int first, std::vector<int> pocketed = {}, bool rail = true) {
  ShotSummary s;
  s.first_contact = first;
  s.pocketed = std::move(pocketed);
  s.rail_after_contact = rail;
  return s;
}

ShotSummary nineBreak(int first, std::vector<int> pocketed, int to_rail) {
  ShotSummary s = nineHit(first, std::move(pocketed));
  s.object_balls_to_rail = to_rail;
  return s;
}

// A rack past its break, A to shoot, with `balls` on the table.
Rack afterBreak(RuleSet rules, std::vector<int> balls) {
  return Rack(rules, balls, false);
}

struct Case {
  const char* name;
  ShotSummary shot;
  Foul foul;
  Player next;
  bool ball_in_hand;
};

}  // namespace

TEST(WpaRules, ShotTable) {
  ShotSummary scratch = nineHit(1, {2});
  scratch.cue_pocketed = true;
  ShotSummary nothing;
  const Case cases[] = {
      {"legal pot keeps the turn", nineHit(1, {3}), Foul::None, Player::A, false},
      {"legal miss with a rail passes the turn", nineHit(1), Foul::None, Player::B, false},
      {"scratch", scratch, Foul::Scratch, Player::B, true},
      {"wrong ball first", nineHit(2, {1}), Foul::WrongBallFirst, Player::B, true},
      {"no contact", nothing, Foul::NoContact, Player::B, true},
      {"no rail after contact", nineHit(1, {}, false), Foul::NoRail, Player::B, true},
      {"a pot needs no rail", nineHit(1, {1}, false), Foul::None, Player::A, false},
  };
  for (const Case& c : cases) {
    Rack rack = afterBreak(RuleSet::Wpa, kNineBalls);
    const auto v = rack.shoot(c.shot);
    EXPECT_EQ(v.foul, c.foul) << c.name;
    EXPECT_EQ(v.next, c.next) << c.name;
    EXPECT_EQ(v.ball_in_hand, c.ball_in_hand) << c.name;
    EXPECT_EQ(rack.shooter(), c.next) << c.name;
    EXPECT_FALSE(v.winner) << c.name;
  }
}

TEST(WpaRules, FoulNamesAreTheIssues) {
  EXPECT_STREQ(foulName(Foul::Scratch), "scratch");
  EXPECT_STREQ(foulName(Foul::WrongBallFirst), "wrong-ball-first");
  EXPECT_STREQ(foulName(Foul::NoContact), "no-contact");
  EXPECT_STREQ(foulName(Foul::NoRail), "no-rail");
  EXPECT_STREQ(foulName(Foul::BadBreak), "bad-break");
  EXPECT_STREQ(foulName(Foul::ThreeFouls), "three-fouls");
}

TEST(WpaRules, BreakNeedsTheOneFirstAndAPotOrFourToRail) {
  {
    Rack rack(RuleSet::Wpa, kNineBalls);
    EXPECT_TRUE(rack.isBreak());
    const auto v = rack.shoot(nineBreak(1, {}, 4));
    EXPECT_TRUE(v.legal());
    EXPECT_EQ(v.next, Player::B);
    EXPECT_TRUE(v.push_out_available);
  }
  {
    Rack rack(RuleSet::Wpa, kNineBalls);
    const auto v = rack.shoot(nineBreak(1, {}, 3));
    EXPECT_EQ(v.foul, Foul::BadBreak);
    EXPECT_TRUE(v.ball_in_hand);
    EXPECT_EQ(v.next, Player::B);
  }
  {
    Rack rack(RuleSet::Wpa, kNineBalls);
    const auto v = rack.shoot(nineBreak(2, {5}, 6));
    EXPECT_EQ(v.foul, Foul::BadBreak);
  }
  {
    Rack rack(RuleSet::Wpa, kNineBalls);
    const auto v = rack.shoot(nineBreak(1, {5}, 0));
    EXPECT_TRUE(v.legal());
    EXPECT_EQ(v.next, Player::A);
    EXPECT_EQ(rack.ballOn(), 1);
  }
}

TEST(WpaRules, NineOnALegalBreakWins) {
  Rack rack(RuleSet::Wpa, kNineBalls);
  const auto v = rack.shoot(nineBreak(1, {9}, 2));
  ASSERT_TRUE(v.winner);
  EXPECT_EQ(*v.winner, Player::A);
  EXPECT_TRUE(rack.over());
  EXPECT_THROW(rack.shoot(nineHit(1)), std::logic_error);
}

TEST(WpaRules, NineOnAFoulIsSpottedOthersStayDown) {
  Rack rack = afterBreak(RuleSet::Wpa, kNineBalls);
  const auto v = rack.shoot(nineHit(3, {9, 4}));
  EXPECT_EQ(v.foul, Foul::WrongBallFirst);
  EXPECT_EQ(v.to_spot, std::vector<int>{9});
  EXPECT_FALSE(v.winner);
  const auto& on = rack.ballsOnTable();
  EXPECT_NE(std::find(on.begin(), on.end(), 9), on.end());
  EXPECT_EQ(std::find(on.begin(), on.end(), 4), on.end());
}

TEST(WpaRules, NineOnALegalShotWinsCombinationsIncluded) {
  Rack rack = afterBreak(RuleSet::Wpa, {3, 9});
  const auto v = rack.shoot(nineHit(3, {9}));
  ASSERT_TRUE(v.winner);
  EXPECT_EQ(*v.winner, Player::A);
}

TEST(WpaRules, LowestBallMustBeHitFirst) {
  Rack rack = afterBreak(RuleSet::Wpa, {2, 5, 9});
  EXPECT_EQ(rack.ballOn(), 2);
  EXPECT_EQ(rack.shoot(nineHit(5, {5})).foul, Foul::WrongBallFirst);
  EXPECT_EQ(rack.ballOn(), 2);  // the 5 stays down, the 2 is still on
}

TEST(WpaRules, PushOutThenPassOrShoot) {
  for (bool shoot : {true, false}) {
    Rack rack(RuleSet::Wpa, kNineBalls);
    rack.shoot(nineBreak(1, {}, 5));  // B to shoot, push-out available
    EXPECT_TRUE(rack.pushOutAvailable());
    ShotSummary no_contact;  // a push-out need not touch a ball or a rail
    const auto v = rack.shoot(no_contact, true);
    EXPECT_TRUE(v.legal());
    EXPECT_TRUE(v.awaiting_decision);
    EXPECT_EQ(v.next, Player::A);
    EXPECT_THROW(rack.shoot(nineHit(1)), std::logic_error);  // must decide first
    rack.decide(shoot);
    EXPECT_EQ(rack.shooter(), shoot ? Player::A : Player::B);
    EXPECT_FALSE(rack.pushOutAvailable());
    EXPECT_THROW(rack.shoot(nineHit(1), true), std::logic_error);  // only right after the break
  }
}

TEST(WpaRules, PushOutOnlyRightAfterTheBreak) {
  Rack rack(RuleSet::Wpa, kNineBalls);
  EXPECT_THROW(rack.shoot(nineBreak(1, {}, 5), true), std::logic_error);
  Rack later = afterBreak(RuleSet::Wpa, kNineBalls);
  EXPECT_THROW(later.shoot(nineHit(1), true), std::logic_error);
  EXPECT_THROW(later.decide(true), std::logic_error);
}

TEST(WpaRules, PushOutScratchIsAFoulAndNineIsSpotted) {
  Rack rack(RuleSet::Wpa, kNineBalls);
  rack.shoot(nineBreak(1, {}, 5));
  ShotSummary s = nineHit(4, {9});
  s.cue_pocketed = true;
  const auto v = rack.shoot(s, true);
  EXPECT_EQ(v.foul, Foul::Scratch);
  EXPECT_TRUE(v.ball_in_hand);
  EXPECT_FALSE(v.awaiting_decision);
  EXPECT_EQ(v.to_spot, std::vector<int>{9});
}

TEST(WpaRules, ThreeFoulsInARowLoseTheRack) {
  Rack rack = afterBreak(RuleSet::Wpa, kNineBalls);
  ShotSummary miss;
  rack.shoot(miss);                 // A foul 1
  rack.shoot(nineHit(1));           // B legal miss
  rack.shoot(miss);                 // A foul 2
  rack.shoot(nineHit(1));           // B
  const auto v = rack.shoot(miss);  // A foul 3
  EXPECT_EQ(v.foul, Foul::ThreeFouls);
  ASSERT_TRUE(v.winner);
  EXPECT_EQ(*v.winner, Player::B);
}

TEST(WpaRules, ALegalShotClearsTheFoulCount) {
  Rack rack = afterBreak(RuleSet::Wpa, kNineBalls);
  ShotSummary miss;
  rack.shoot(miss);        // A foul 1
  rack.shoot(nineHit(1));  // B
  rack.shoot(miss);        // A foul 2
  rack.shoot(nineHit(1));  // B
  rack.shoot(nineHit(1));  // A legal
  EXPECT_EQ(rack.consecutiveFouls(Player::A), 0);
  rack.shoot(nineHit(1));  // B
  EXPECT_EQ(rack.shoot(miss).foul, Foul::NoContact);
}

TEST(PaperRules, FoulsAndTurns) {
  ShotSummary scratch = nineHit(1, {2});
  scratch.cue_pocketed = true;
  ShotSummary nothing;
  const Case cases[] = {
      {"legal pot keeps the turn", nineHit(1, {3}), Foul::None, Player::A, false},
      {"miss passes the turn", nineHit(1, {}, false), Foul::None, Player::B, false},
      {"scratch", scratch, Foul::Scratch, Player::B, false},
      {"wrong ball first", nineHit(2), Foul::WrongBallFirst, Player::B, false},
      {"no ball hit", nothing, Foul::NoContact, Player::B, false},
  };
  for (const Case& c : cases) {
    Rack rack(RuleSet::Paper, kNineBalls);
    const auto v = rack.shoot(c.shot);
    EXPECT_EQ(v.foul, c.foul) << c.name;
    EXPECT_EQ(v.next, c.next) << c.name;
    EXPECT_EQ(v.ball_in_hand, c.ball_in_hand) << c.name;
  }
}

TEST(PaperRules, ScratchSendsTheCueBallToTheHeadSpot) {
  Rack rack(RuleSet::Paper, kNineBalls);
  ShotSummary s = nineHit(1);
  s.cue_pocketed = true;
  EXPECT_TRUE(rack.shoot(s).cue_to_head_spot);
}

TEST(PaperRules, NoBreakRulesNoPushOut) {
  Rack rack(RuleSet::Paper, kNineBalls);
  const auto v = rack.shoot(nineBreak(1, {}, 0));  // WPA would call this a bad break
  EXPECT_TRUE(v.legal());
  EXPECT_FALSE(v.push_out_available);
  EXPECT_THROW(rack.shoot(nineHit(1), true), std::logic_error);
}

TEST(PaperRules, NineLegallyWinsNineOnAFoulLoses) {
  {
    Rack rack(RuleSet::Paper, {1, 9});
    const auto v = rack.shoot(nineHit(1, {9}));
    ASSERT_TRUE(v.winner);
    EXPECT_EQ(*v.winner, Player::A);
  }
  {
    Rack rack(RuleSet::Paper, {1, 9});
    const auto v = rack.shoot(nineHit(9, {9}));
    EXPECT_EQ(v.foul, Foul::WrongBallFirst);
    ASSERT_TRUE(v.winner);
    EXPECT_EQ(*v.winner, Player::B);
  }
}

TEST(PaperRules, AllBallsDownEndsTheGame) {
  Rack rack(RuleSet::Paper, {1, 2});
  const auto v = rack.shoot(nineHit(1, {1, 2}));
  ASSERT_TRUE(v.winner);
  EXPECT_EQ(*v.winner, Player::A);
}

TEST(NineBallRules, IsTheDefaultGameBehindTheOneInterface) {
  Rack rack(RuleSet::Wpa, kNineBalls);
  EXPECT_EQ(rack.game(), nineball::rules::Game::NineBall);
  EXPECT_STREQ(gameName(rack.game()), "nine-ball");
  EXPECT_EQ(rack.legalFirstBalls(), std::vector<int>{1});
  EXPECT_FALSE(rack.callRequired());
  EXPECT_TRUE(rack.groups().open());
  rack.shoot(nineBreak(1, {}, 5));
  const auto v = rack.shoot(ShotSummary{}, true);
  EXPECT_EQ(v.decision, nineball::rules::Decision::PlayOrPass);
  EXPECT_EQ(rack.pendingDecision(), nineball::rules::Decision::PlayOrPass);
}

TEST(NineBallRules, SameBookForEveryRack) {
  using nineball::rules::Game;
  EXPECT_EQ(&nineball::rules::ruleBook(Game::NineBall, RuleSet::Paper),
            &nineball::rules::ruleBook(Game::NineBall, RuleSet::Paper));
  EXPECT_EQ(nineball::rules::ruleBook(Game::TenBall).game(), Game::TenBall);
}
