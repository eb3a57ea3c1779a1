// Snooker's rules, one test a rule of the WPBSA's Official Rules (section 3: 3.4 the end of the
// frame and the re-spotted black, 3.5-3.7 play and spotting, 3.10 penalties, 3.12 free ball,
// 3.13 touching ball, 3.14 foul and a miss, 3.15 after a foul), fed with hand-made shot
// summaries. The geometry the match supplies (snookered, touching) is set by hand here; its own
// tests are in tests/play/snookered_test.cpp.
#include "rules/snooker.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "nineball/rules.hpp"
#include "nineball/snooker_rack.hpp"

namespace nineball::rules {
namespace {

constexpr int kYellow = 16;
constexpr int kGreen = 17;
constexpr int kBrown = 18;
constexpr int kBlue = 19;
constexpr int kPink = 20;
constexpr int kBlack = 21;

std::vector<int> reds() {
  std::vector<int> r;
  for (int b = 1; b <= 15; ++b) r.push_back(b);
  return r;
}
std::vector<int> colours() {
  return {kYellow, kGreen, kBrown, kBlue, kPink, kBlack};
}
std::vector<int> fullSet() {
  std::vector<int> all = reds();
  for (int c : colours()) all.push_back(c);
  return all;
}

Rack frame(std::vector<int> balls = fullSet()) {
  return Rack(Game::Snooker, RuleSet::Wpbsa, std::move(balls), false);
}

ShotSummary hit(int first, std::vector<int> potted = {}) {
  ShotSummary s;
  s.first_contact = first;
  s.pocketed = std::move(potted);
  return s;
}

ShotSummary nothingHit() {
  return ShotSummary{};
}

ShotSummary called(int ball, ShotSummary s) {
  s.call = Call{ball, PocketId::TopRight};
  return s;
}

TEST(SnookerRules, NamesAndBook) {
  EXPECT_EQ(gameFromName("snooker"), Game::Snooker);
  EXPECT_STREQ(gameName(Game::Snooker), "snooker");
  EXPECT_EQ(ruleSetFromName("wpbsa"), RuleSet::Wpbsa);
  EXPECT_STREQ(ruleSetName(RuleSet::Wpbsa), "wpbsa");
  EXPECT_EQ(ruleBook(Game::Snooker, RuleSet::Wpbsa).game(), Game::Snooker);
  EXPECT_THROW(ruleBook(Game::Snooker, RuleSet::Wpa), std::invalid_argument);
  EXPECT_STREQ(foulName(Foul::PottedNotOn), "potted-not-on");
  EXPECT_STREQ(foulName(Foul::ThreeMisses), "three-misses");
}

// 3.5: the first stroke of each turn is at a red while reds remain.
TEST(SnookerRules, TheBallOnIsARedWhileRedsRemain) {
  const Rack r(Game::Snooker, RuleSet::Wpbsa, fullSet());
  EXPECT_EQ(r.legalFirstBalls(), reds());
  EXPECT_EQ(r.ballOn(), 1);
  EXPECT_FALSE(r.callRequired());
}

// 3.5, 3.10: a red potted scores 1 and the striker goes on to a colour of his choice.
TEST(SnookerRules, ARedPottedScoresOneAndPutsTheColoursOn) {
  Rack r = frame();
  const Verdict v = r.shoot(hit(3, {3}));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.points[0], 1);
  EXPECT_EQ(v.next, Player::A);
  EXPECT_EQ(r.legalFirstBalls(), colours());
  EXPECT_EQ(r.currentRun(), 1);
  EXPECT_EQ(r.ballsOnTable().size(), 20u);
}

// 3.5(b): every red potted in one stroke counts.
TEST(SnookerRules, SeveralRedsInOneStrokeAllCount) {
  Rack r = frame();
  EXPECT_EQ(r.shoot(hit(3, {3, 7, 9})).points[0], 3);
  EXPECT_EQ(r.score(Player::A), 3);
}

// 3.5, 3.6: the colour nominated after a red scores its value and is re-spotted; reds are on
// again.
TEST(SnookerRules, TheNominatedColourScoresItsValueAndIsRespotted) {
  Rack r = frame();
  r.shoot(hit(3, {3}));
  const Verdict v = r.shoot(called(kBlack, hit(kBlack, {kBlack})));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.nominated, kBlack);
  EXPECT_EQ(v.points[0], 7);
  EXPECT_EQ(v.to_spot, std::vector<int>{kBlack});
  EXPECT_TRUE(r.state().has(kBlack));
  EXPECT_EQ(r.score(Player::A), 8);
  EXPECT_EQ(r.currentRun(), 8);
  EXPECT_EQ(r.legalFirstBalls().front(), 1);  // reds again
}

// nineball's form of the nomination: without a call the colour first hit is nominated.
TEST(SnookerRules, WithoutACallTheFirstColourHitIsNominated) {
  Rack r = frame();
  r.shoot(hit(3, {3}));
  const Verdict v = r.shoot(hit(kBlue, {kBlue}));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.nominated, kBlue);
  EXPECT_EQ(v.points[0], 5);
}

// 3.10: first hitting another colour than the one nominated is a foul worth the higher value.
TEST(SnookerRules, HittingAnotherColourThanTheNominatedOneIsAFoul) {
  Rack r = frame();
  r.shoot(hit(3, {3}));
  const Verdict v = r.shoot(called(kGreen, hit(kBlack)));
  EXPECT_EQ(v.foul, Foul::WrongBallFirst);
  EXPECT_EQ(v.points[1], 7);
  EXPECT_EQ(r.score(Player::B), 7);
  EXPECT_EQ(r.currentRun(), 0);
}

// 3.10: missing every ball costs the value of the ball on, at least four.
TEST(SnookerRules, MissingAllBallsCostsFour) {
  Rack r = frame();
  const Verdict v = r.shoot(nothingHit());
  EXPECT_EQ(v.foul, Foul::NoContact);
  EXPECT_EQ(v.points[1], 4);
  EXPECT_EQ(v.next, Player::B);
  EXPECT_FALSE(v.ball_in_hand);
}

// 3.10: first hitting a ball not on costs its value when it is higher than four.
TEST(SnookerRules, FirstHittingABallNotOnCostsItsValue) {
  Rack r = frame();
  const Verdict v = r.shoot(hit(kPink));
  EXPECT_EQ(v.foul, Foul::WrongBallFirst);
  EXPECT_EQ(v.points[1], 6);
  r = frame();
  EXPECT_EQ(r.shoot(hit(kGreen)).points[1], 4);
}

// 3.10: potting a ball not on costs the highest ball involved; the red potted with it stays
// down and the colour is re-spotted (3.6).
TEST(SnookerRules, PottingABallNotOnIsAFoulAndTheColourComesBack) {
  Rack r = frame();
  const Verdict v = r.shoot(hit(1, {1, kPink}));
  EXPECT_EQ(v.foul, Foul::PottedNotOn);
  EXPECT_EQ(v.points[1], 6);
  EXPECT_EQ(v.points[0], 0);
  EXPECT_EQ(v.to_spot, std::vector<int>{kPink});
  EXPECT_FALSE(r.state().has(1));
  EXPECT_TRUE(r.state().has(kPink));
}

// 3.10: after a red, potting a red (not on: a colour is) is a foul.
TEST(SnookerRules, ARedIsNotOnAfterARed) {
  Rack r = frame();
  r.shoot(hit(3, {3}));
  const Verdict v = r.shoot(hit(kYellow, {4}));
  EXPECT_EQ(v.foul, Foul::PottedNotOn);
  EXPECT_EQ(v.points[1], 4);
  EXPECT_FALSE(r.state().has(4));  // a red potted on a foul stays down
}

// 3.10: an in-off costs four, or the nominated colour's value; the cue ball is in hand.
TEST(SnookerRules, AnInOffCostsTheValueOfTheBallOnAndGivesBallInHand) {
  Rack r = frame();
  ShotSummary s = hit(1, {1});
  s.cue_pocketed = true;
  Verdict v = r.shoot(s);
  EXPECT_EQ(v.foul, Foul::Scratch);
  EXPECT_EQ(v.points[1], 4);
  EXPECT_TRUE(v.ball_in_hand);
  EXPECT_FALSE(r.state().has(1));

  r = frame();
  r.shoot(hit(3, {3}));
  s = called(kBlack, hit(kBlack));
  s.cue_pocketed = true;
  v = r.shoot(s);
  EXPECT_EQ(v.points[1], 7);
}

// 3.15: after a foul the opponent plays, or asks the offender to play again.
TEST(SnookerRules, AfterAFoulTheOpponentPlaysOrPutsTheOffenderBack) {
  Rack r = frame();
  ShotSummary in_off = hit(1);
  in_off.cue_pocketed = true;
  Verdict v = r.shoot(in_off);
  EXPECT_EQ(v.decision, Decision::PlayOrPutBack);
  EXPECT_TRUE(r.awaitingDecision());
  EXPECT_EQ(r.shooter(), Player::B);
  EXPECT_THROW(r.shoot(hit(1)), std::logic_error);
  Rack play = r;
  play.decide(true);
  EXPECT_EQ(play.shooter(), Player::B);
  r.decide(false);
  EXPECT_EQ(r.shooter(), Player::A);
  EXPECT_NO_THROW(r.shoot(hit(1)));
}

// 3.12: snookered after a foul, the striker gets a free ball: any ball nominated counts as a
// red while reds are on, scores 1 and is re-spotted; a colour is then on.
TEST(SnookerRules, AFreeBallCountsAsTheBallOnAndIsRespotted) {
  Rack r = frame();
  r.shoot(nothingHit());
  rules::stateFreeBall(r, true);
  EXPECT_TRUE(rules::freeBall(r));
  EXPECT_EQ(r.legalFirstBalls(), fullSet());
  r.decide(true);
  const Verdict v = r.shoot(called(kBlack, hit(kBlack, {kBlack, 2})));
  EXPECT_TRUE(v.legal());
  EXPECT_TRUE(v.free_ball);
  EXPECT_EQ(v.nominated, kBlack);
  EXPECT_EQ(v.points[1], 2);  // the free ball as a red, and the red
  EXPECT_EQ(v.to_spot, std::vector<int>{kBlack});
  EXPECT_EQ(r.legalFirstBalls(), colours());
  EXPECT_FALSE(rules::freeBall(r));
}

// 3.12(b): the free ball nominated must be hit first; a red potted after it still scores.
TEST(SnookerRules, TheNominatedFreeBallMustBeHitFirst) {
  Rack r = frame();
  r.shoot(nothingHit());
  rules::stateFreeBall(r, true);
  r.decide(true);
  Rack after = r;
  Verdict v = r.shoot(called(kBlack, hit(2)));
  EXPECT_EQ(v.foul, Foul::WrongBallFirst);
  EXPECT_EQ(v.points[0], 4);  // the free ball is worth the ball on's value
  v = after.shoot(called(kBlack, hit(kBlack, {2})));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.points[1], 1);
}

// 3.12: a free ball in the colours' order scores the ball on's value; a foul on it costs the
// ball on's value, not the nominated ball's.
TEST(SnookerRules, AFreeBallInTheColoursTakesTheBallOnsValue) {
  Rack r = frame({kYellow, kGreen, kBlack});
  r.shoot(nothingHit());  // A fouls: B 4
  rules::stateFreeBall(r, true);
  r.decide(true);
  Rack fouled = r;
  Verdict v = r.shoot(called(kBlack, hit(kBlack, {kBlack})));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.points[1], 2);
  EXPECT_EQ(v.to_spot, std::vector<int>{kBlack});
  EXPECT_EQ(r.ballOn(), kYellow);
  ShotSummary in_off = called(kBlack, hit(kBlack));
  in_off.cue_pocketed = true;
  v = fouled.shoot(in_off);
  EXPECT_EQ(v.points[0], 4);
}

// 3.12(f): when the offender is put back in, the free ball is void; and it follows a foul only.
TEST(SnookerRules, AFreeBallIsVoidWhenTheOffenderPlaysAgain) {
  Rack r = frame();
  r.shoot(nothingHit());
  rules::stateFreeBall(r, true);
  r.decide(false);
  EXPECT_FALSE(rules::freeBall(r));
  EXPECT_EQ(r.legalFirstBalls(), reds());
  Rack legal = frame();
  legal.shoot(hit(1));
  rules::stateFreeBall(legal, true);
  EXPECT_FALSE(rules::freeBall(legal));
}

// 3.14 in nineball's form: a foul that fails to first hit a ball on is a miss unless the
// striker was snookered before the stroke or needed snookers.
TEST(SnookerRules, AMissIsAFailureToHitTheBallOnWhenInView) {
  Rack r = frame();
  Verdict v = r.shoot(hit(kPink));
  EXPECT_TRUE(v.miss);
  EXPECT_EQ(v.decision, Decision::PlayPutBackOrReplace);

  r = frame();
  ShotSummary snookered = hit(kPink);
  snookered.snookered_before = true;
  v = r.shoot(snookered);
  EXPECT_FALSE(v.miss);
  EXPECT_EQ(v.decision, Decision::PlayOrPutBack);

  r = frame();
  ShotSummary in_off = hit(1);
  in_off.cue_pocketed = true;
  EXPECT_FALSE(r.shoot(in_off).miss);  // the ball on was hit
}

TEST(SnookerRules, NoMissWhenTheStrikerNeedsSnookers) {
  // Yellow and black left (9 points): B is 12 behind after A's fouls, so B needs snookers.
  Rack r = frame({kYellow, kBlack});
  r.shoot(hit(kBlack));  // A fouls: B 7
  r.decide(false);
  r.shoot(hit(kBlack));  // again: B 14
  r.decide(true);        // B plays on
  r.shoot(hit(kYellow, {kYellow}));
  r.shoot(hit(kBlack));  // B plays the black without potting it: A to play, 16 behind
  EXPECT_EQ(r.score(Player::B), 16);
  ASSERT_EQ(r.shooter(), Player::A);
  EXPECT_TRUE(rules::snookersRequired(r, Player::A));
  EXPECT_FALSE(r.shoot(nothingHit()).miss);
}

// 3.14: after a miss the balls may be replaced and the offender plays again; the penalty stays.
TEST(SnookerRules, AfterAMissTheBallsMayBeReplaced) {
  Rack r = frame();
  const Verdict v = r.shoot(hit(kPink, {5}));  // hits the pink first, a red drops
  EXPECT_TRUE(v.miss);
  EXPECT_FALSE(r.state().has(5));
  rules::replaceAfterMiss(r);
  EXPECT_EQ(r.shooter(), Player::A);
  EXPECT_TRUE(r.state().has(5));
  EXPECT_EQ(r.score(Player::B), 6);
  EXPECT_FALSE(r.awaitingDecision());
  Rack plain = frame();
  plain.shoot(hit(1));  // legal: no decision
  EXPECT_THROW(rules::replaceAfterMiss(plain), std::logic_error);
}

// 3.14(h): the third miss in a row with a ball on in view loses the frame.
TEST(SnookerRules, ThreeMissesInARowLoseTheFrame) {
  Rack r = frame();
  r.shoot(hit(kPink));
  rules::replaceAfterMiss(r);
  r.shoot(hit(kPink));
  rules::replaceAfterMiss(r);
  const Verdict v = r.shoot(hit(kPink));
  EXPECT_EQ(v.foul, Foul::ThreeMisses);
  EXPECT_EQ(v.winner, Player::B);
  EXPECT_TRUE(r.over());
  // Played on or put back in between, the misses do not add up.
  Rack played_on = frame();
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(played_on.shoot(hit(kPink)).miss);
    played_on.decide(false);
  }
  EXPECT_FALSE(played_on.over());
  // A stroke that is not a miss starts the count again.
  Rack again = frame();
  again.shoot(hit(kPink));
  rules::replaceAfterMiss(again);
  again.shoot(hit(1));
  EXPECT_EQ(again.state().snooker.misses[0], 0);
}

// 3.13: a touching ball on counts as hit when the cue ball plays away from it; one not on
// does not.
TEST(SnookerRules, ATouchingBallOnCountsAsHit) {
  Rack r = frame();
  ShotSummary away = nothingHit();
  away.touching_before = {4};
  const Verdict v = r.shoot(away);
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.next, Player::B);
  Rack other = frame();
  away.touching_before = {kPink};
  EXPECT_EQ(other.shoot(away).foul, Foul::NoContact);
}

// 3.5-3.6: after the last red and its colour, the colours in ascending order, staying down.
TEST(SnookerRules, AfterTheLastRedTheColoursGoInOrder) {
  std::vector<int> balls = colours();
  balls.insert(balls.begin(), 7);
  Rack r = frame(balls);
  r.shoot(hit(7, {7}));
  EXPECT_EQ(r.legalFirstBalls(), colours());
  const Verdict v = r.shoot(hit(kPink, {kPink}));  // the colour after the last red
  EXPECT_EQ(v.to_spot, std::vector<int>{kPink});
  EXPECT_EQ(r.legalFirstBalls(), std::vector<int>{kYellow});
  r.shoot(hit(kYellow, {kYellow}));
  EXPECT_FALSE(r.state().has(kYellow));
  EXPECT_EQ(r.ballOn(), kGreen);
  EXPECT_EQ(r.score(Player::A), 1 + 6 + 2);
  const Verdict wrong = r.shoot(hit(kGreen, {kBrown}));
  EXPECT_EQ(wrong.foul, Foul::PottedNotOn);
  EXPECT_EQ(wrong.points[1], 4);
  EXPECT_EQ(wrong.to_spot, std::vector<int>{kBrown});
}

// 3.4: the black potted last ends the frame, the higher score winning.
TEST(SnookerRules, TheLastBlackEndsTheFrame) {
  Rack r = frame({kPink, kBlack});
  r.shoot(hit(kPink, {kPink}));
  const Verdict v = r.shoot(hit(kBlack, {kBlack}));
  EXPECT_EQ(v.winner, Player::A);
  EXPECT_EQ(r.score(Player::A), 13);
  EXPECT_TRUE(r.over());
}

// 3.4: with the black alone, the first foul ends the frame too.
TEST(SnookerRules, WithTheBlackAloneAFoulEndsTheFrame) {
  Rack r = frame({kBlack});
  const Verdict v = r.shoot(nothingHit());
  EXPECT_EQ(v.points[1], 7);
  EXPECT_EQ(v.winner, Player::B);
}

// 3.4: level after the black: the black is re-spotted, the cue ball in hand, and the first
// score or foul wins. Judged on a state set by hand (the scores level before the last black).
TEST(SnookerRules, ALevelFrameIsDecidedOnARespottedBlack) {
  const SnookerRules book;
  RackState s;
  s.on_table = {kBlack};
  s.score[0] = 30;
  s.score[1] = 37;
  Verdict v = book.judge(s, hit(kBlack, {kBlack}), false);
  EXPECT_TRUE(v.black_respotted);
  EXPECT_FALSE(v.winner);
  EXPECT_EQ(v.to_spot, std::vector<int>{kBlack});
  EXPECT_TRUE(v.ball_in_hand);
  EXPECT_EQ(v.next, Player::B);
  EXPECT_TRUE(s.snooker.respotted_black);
  EXPECT_TRUE(s.has(kBlack));

  s.score[0] = 37;
  s.shooter = Player::B;
  RackState fouled = s;
  v = book.judge(s, hit(kBlack, {kBlack}), false);
  EXPECT_EQ(v.winner, Player::B);
  v = book.judge(fouled, nothingHit(), false);
  EXPECT_EQ(v.winner, Player::A);
  EXPECT_EQ(v.points[0], 7);
}

// Points remaining: 8 a red, the colours' 27, 7 more while a colour is on after a red.
TEST(SnookerRules, PointsRemaining) {
  Rack r = frame();
  EXPECT_EQ(r.pointsRemaining(), 147);
  r.shoot(hit(3, {3}));
  EXPECT_EQ(r.pointsRemaining(), 14 * 8 + 7 + 27);
  EXPECT_EQ(frame(colours()).pointsRemaining(), 27);
  EXPECT_EQ(frame({kPink, kBlack}).pointsRemaining(), 13);
  EXPECT_FALSE(rules::snookersRequired(r, Player::B));
}

}  // namespace
}  // namespace nineball::rules
