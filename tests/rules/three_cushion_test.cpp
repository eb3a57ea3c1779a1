// Three-cushion's rules, one test a rule of the UMB's world rules of carom billiard (art. 23
// the opening, art. 29 the equal innings, chapter V art. 83 the point), fed with hand-made
// shot summaries: what the shooter's ball touched, in order, and the cushions it had met
// before each touch.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "nineball/carom_rack.hpp"
#include "nineball/rules.hpp"

namespace rules = nineball::rules;
using nineball::rules::Foul;
using nineball::rules::Game;
using nineball::rules::Player;
using nineball::rules::Rack;
using nineball::rules::RuleSet;
using nineball::rules::ShotSummary;
using nineball::rules::Verdict;

namespace {

constexpr int kWhite = 0;
constexpr int kYellow = 1;
constexpr int kRed = 2;

// One step of the cue ball's path: a cushion, or a touch of a ball.
struct Step {
  bool cushion;
  int ball;
};
const Step kCushion{true, -1};
Step touch(int ball) {
  return {false, ball};
}

ShotSummary path(std::vector<Step> steps) {
  ShotSummary s;
  for (const Step& step : steps) {
    if (step.cushion) {
      ++s.cue_cushions;
      if (s.first_contact) s.rail_after_contact = true;
      continue;
    }
    if (!s.first_contact) s.first_contact = step.ball;
    s.cue_touches.push_back(step.ball);
    s.cue_cushions_before.push_back(s.cue_cushions);
  }
  return s;
}

// A shot by A's white (yellow and red are its object balls) that scores.
ShotSummary pointFor(int first, int second) {
  return path({touch(first), kCushion, kCushion, kCushion, touch(second)});
}

ShotSummary miss() {
  return path({touch(kRed), kCushion, kCushion});
}

// A game to `points` with the opening shot played (A scores on the red).
Rack opened(int points = 25) {
  Rack r(Game::ThreeCushion, RuleSet::Umb, {kYellow, kRed});
  r.setTargetPoints(points);
  EXPECT_EQ(r.shoot(pointFor(kRed, kYellow)).points[0], 1);
  return r;
}

TEST(ThreeCushion, APointIsBothObjectBallsWithThreeCushionsBeforeTheSecond) {
  Rack r = opened();
  const Verdict v = r.shoot(pointFor(kYellow, kRed));
  EXPECT_TRUE(v.legal());
  EXPECT_EQ(v.points[0], 1);
  EXPECT_EQ(v.cushions, 3);
  EXPECT_EQ(r.score(Player::A), 2);
}

TEST(ThreeCushion, TwoCushionsBeforeTheSecondBallIsNoPoint) {
  Rack r = opened();
  const Verdict v = r.shoot(path({touch(kYellow), kCushion, kCushion, touch(kRed), kCushion}));
  EXPECT_EQ(v.points[0], 0);
  EXPECT_EQ(v.cushions, 2);
  EXPECT_EQ(v.next, Player::B);
}

TEST(ThreeCushion, CushionsAfterTheSecondBallDoNotCount) {
  Rack r = opened();
  const Verdict v =
      r.shoot(path({touch(kYellow), touch(kRed), kCushion, kCushion, kCushion, kCushion}));
  EXPECT_EQ(v.points[0], 0);
  EXPECT_EQ(v.cushions, 0);
}

TEST(ThreeCushion, TheCushionsMayComeBeforeTheFirstBallAndOneCushionCountsEachTime) {
  Rack r = opened();
  // Cushion first ("ball-first" is not required): three cushions, then both balls.
  EXPECT_EQ(r.shoot(path({kCushion, kCushion, kCushion, touch(kRed), touch(kYellow)})).points[0],
            1);
  // Split between before and after the first ball.
  EXPECT_EQ(r.shoot(path({kCushion, touch(kRed), kCushion, kCushion, touch(kYellow)})).points[0],
            1);
  // The same cushion met twice (a summary counts meetings, not cushions): three.
  EXPECT_EQ(r.shoot(pointFor(kYellow, kRed)).cushions, 3);
}

TEST(ThreeCushion, OneObjectBallTouchedTwiceIsNotBoth) {
  Rack r = opened();
  const Verdict v =
      r.shoot(path({touch(kRed), kCushion, kCushion, kCushion, touch(kRed), kCushion}));
  EXPECT_EQ(v.points[0], 0);
  EXPECT_EQ(v.cushions, 4);  // every cushion of a shot that never reached a second ball
}

TEST(ThreeCushion, EachPlayerStrikesTheirOwnBall) {
  Rack r = opened();
  EXPECT_EQ(r.cueBall(), kWhite);  // the opener plays the white
  r.shoot(miss());
  EXPECT_EQ(r.shooter(), Player::B);
  EXPECT_EQ(r.cueBall(), kYellow);
  EXPECT_EQ(r.legalFirstBalls(), (std::vector<int>{kWhite, kRed}));
  // B's point: the white and the red are B's object balls.
  EXPECT_EQ(r.shoot(pointFor(kWhite, kRed)).points[1], 1);
  EXPECT_EQ(r.score(Player::B), 1);
}

TEST(ThreeCushion, APointPlaysOnAndAMissEndsTheInning) {
  Rack r = opened();
  EXPECT_EQ(r.shooter(), Player::A);
  EXPECT_EQ(rules::innings(r, Player::A), 1);
  r.shoot(pointFor(kYellow, kRed));
  EXPECT_EQ(r.currentRun(), 2);
  r.shoot(miss());
  EXPECT_EQ(r.shooter(), Player::B);
  EXPECT_EQ(r.currentRun(), 0);
  EXPECT_EQ(rules::highRun(r, Player::A), 2);
  r.shoot(miss());
  EXPECT_EQ(rules::innings(r, Player::B), 1);
  EXPECT_EQ(r.shooter(), Player::A);
  r.shoot(pointFor(kRed, kYellow));
  EXPECT_EQ(rules::innings(r, Player::A), 2);
  EXPECT_EQ(rules::highRun(r, Player::A), 2);  // a run of one does not beat two
}

TEST(ThreeCushion, TheOpeningShotGoesStraightOntoTheRed) {
  for (const ShotSummary& wrong : {pointFor(kYellow, kRed), path({kCushion, touch(kRed), kCushion,
                                                                  kCushion, touch(kYellow)})}) {
    Rack r(Game::ThreeCushion, RuleSet::Umb, {kYellow, kRed});
    EXPECT_EQ(r.legalFirstBalls(), (std::vector<int>{kRed}));
    const Verdict v = r.shoot(wrong);
    EXPECT_EQ(v.foul, Foul::WrongBallFirst);
    EXPECT_EQ(v.points[0], 0);  // even with both balls and three cushions
    EXPECT_EQ(v.next, Player::B);
  }
  // Only the opening: the next shots may start on either ball, or a cushion.
  Rack r = opened();
  EXPECT_EQ(r.shoot(path({kCushion, kCushion, kCushion, touch(kYellow), touch(kRed)})).foul,
            Foul::None);
  // When the balls are set up again (frozen balls), the next shot is an opening one.
  rules::replayOpening(r);
  EXPECT_EQ(r.shoot(pointFor(kYellow, kRed)).foul, Foul::WrongBallFirst);
}

TEST(ThreeCushion, AMiscueScoresNothing) {
  Rack r = opened();
  ShotSummary s = pointFor(kYellow, kRed);
  s.miscue = true;
  EXPECT_EQ(r.shoot(s).points[0], 0);
  EXPECT_EQ(r.shooter(), Player::B);
}

TEST(ThreeCushion, TheOpenerReachingTheDistanceGivesTheOtherALastInning) {
  Rack r = opened(2);  // A: 1 point, innings 1
  r.shoot(pointFor(kYellow, kRed));
  EXPECT_EQ(r.score(Player::A), 2);
  EXPECT_FALSE(r.over());
  EXPECT_EQ(r.shooter(), Player::B);  // the equalising inning
  r.shoot(pointFor(kWhite, kRed));
  EXPECT_FALSE(r.over());
  const Verdict v = r.shoot(miss());  // one short: A wins
  ASSERT_TRUE(v.winner);
  EXPECT_EQ(*v.winner, Player::A);
  EXPECT_TRUE(r.over());
  EXPECT_EQ(rules::innings(r, Player::A), rules::innings(r, Player::B));
}

TEST(ThreeCushion, BothReachingTheDistanceInEqualInningsIsADraw) {
  Rack r = opened(2);
  r.shoot(pointFor(kYellow, kRed));
  r.shoot(pointFor(kWhite, kRed));
  const Verdict v = r.shoot(pointFor(kRed, kWhite));
  EXPECT_TRUE(v.draw);
  EXPECT_FALSE(v.winner);
  EXPECT_TRUE(r.over());
  EXPECT_TRUE(r.drawn());
}

TEST(ThreeCushion, TheOtherPlayerReachingTheDistanceFirstWins) {
  Rack r = opened(2);
  r.shoot(miss());
  r.shoot(pointFor(kWhite, kRed));
  const Verdict v = r.shoot(pointFor(kRed, kWhite));
  ASSERT_TRUE(v.winner);
  EXPECT_EQ(*v.winner, Player::B);
  EXPECT_THROW(r.shoot(miss()), std::logic_error);
}

}  // namespace
