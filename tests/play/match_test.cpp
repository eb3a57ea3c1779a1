// Scripted racks played through the real physics, checking the verdict of every turn.
#include "nineball/match.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "play/match_turns.hpp"

using nineball::BallState;
using nineball::IllegalAction;
using nineball::Match;
using nineball::MatchSetup;
using nineball::Shot;
using nineball::TurnInput;
using nineball::TurnRecord;
using nineball::Vec2;
using nineball::play_test::shot;
using nineball::rules::Foul;
using nineball::rules::Player;
using nineball::rules::RuleSet;

namespace {

constexpr double kR = 0.028575;

double headingTo(Vec2 from, Vec2 to) {
  return nineball::radToDeg(std::atan2(to.y - from.y, to.x - from.x));
}

MatchSetup layout(std::vector<BallState> balls, RuleSet rules = RuleSet::Wpa) {
  MatchSetup s;
  s.rules = rules;
  s.balls = std::move(balls);
  return s;
}

void expectTurn(const TurnRecord& r, Player shooter, Foul foul, Player next, bool in_hand) {
  EXPECT_EQ(r.shooter, shooter);
  EXPECT_EQ(r.verdict.foul, foul) << foulName(r.verdict.foul);
  EXPECT_EQ(r.verdict.next, next);
  EXPECT_EQ(r.verdict.ball_in_hand, in_hand);
}

// The bottom-right pocket's drop centre: shots here aim straight into it.
Vec2 bottomRightPocket() {
  return nineball::buildTable(nineball::TableDef{}, kR).pockets[3].drop_centre;
}

// The cue ball at `cue`, ball `object` 0.3 m further on the line to the bottom-right pocket,
// ball `other` out of the way; and the shot along that line at `speed`.
struct InLine {
  std::vector<BallState> balls;
  TurnInput shot;
};
InLine inLineWithPocket(Vec2 cue, int object, int other, double speed) {
  const Vec2 pocket = bottomRightPocket();
  const Vec2 dir = nineball::normalized(pocket - cue);
  return {{BallState::at(0, cue), BallState::at(object, cue + dir * 0.3),
           BallState::at(other, {-0.8, 0.3})},
          shot(headingTo(cue, pocket), speed)};
}

}  // namespace

TEST(MatchThroughPhysics, ScratchGivesBallInHand) {
  // A perfectly inelastic hit: the cue ball follows the 1 into the corner pocket.
  const InLine line = inLineWithPocket({0.4, 0.0}, 1, 2, 2.0);
  MatchSetup setup = layout(line.balls);
  setup.physics.ball_restitution = 0.0;
  Match match(setup);
  const TurnRecord r = match.play(line.shot);
  expectTurn(r, Player::A, Foul::Scratch, Player::B, true);
  EXPECT_EQ(r.verdict.pocketed, std::vector<int>{1});
  EXPECT_EQ(r.ball_on, 2);
  EXPECT_TRUE(match.cueInHand());
  // The next shooter must place the cue ball, and not on another ball.
  EXPECT_THROW(match.play(shot(0.0, 1.0)), IllegalAction);
  EXPECT_THROW(match.play(shot(0.0, 1.0, Vec2{-0.8, 0.3})), IllegalAction);
  EXPECT_THROW(match.play(shot(0.0, 1.0, Vec2{5.0, 0.0})), IllegalAction);
  const TurnRecord next =
      match.play(shot(headingTo({-0.3, 0.3}, {-0.8, 0.3}), 1.0, Vec2{-0.3, 0.3}));
  EXPECT_EQ(next.shooter, Player::B);
  EXPECT_TRUE(next.verdict.legal());
}

TEST(MatchThroughPhysics, WrongBallFirst) {
  Match match(layout(
      {BallState::at(0, {-0.5, 0.0}), BallState::at(2, {0.0, 0.0}), BallState::at(1, {0.3, 0.4})}));
  const TurnRecord r = match.play(shot(0.0, 1.5));
  expectTurn(r, Player::A, Foul::WrongBallFirst, Player::B, true);
}

TEST(MatchThroughPhysics, NoRailAfterContact) {
  // A soft full hit in the middle of the table: nothing reaches a cushion.
  Match match(layout({BallState::at(0, {-0.3, 0.0}), BallState::at(1, {0.0, 0.0}),
                      BallState::at(9, {-1.0, 0.4})}));
  const TurnRecord r = match.play(shot(0.0, 0.3));
  expectTurn(r, Player::A, Foul::NoRail, Player::B, true);
  EXPECT_TRUE(r.verdict.pocketed.empty());
}

TEST(MatchThroughPhysics, CombinationOnTheNineWins) {
  const Vec2 pocket = bottomRightPocket();
  const Vec2 cue{0.2, 0.1};
  const Vec2 dir = nineball::normalized(pocket - cue);
  const Vec2 one = cue + dir * 0.4;
  const Vec2 nine = one + dir * (2.0 * kR + 0.01);
  Match match(layout({BallState::at(0, cue), BallState::at(1, one), BallState::at(9, nine),
                      BallState::at(5, {-0.8, -0.3})}));
  const TurnRecord r = match.play(shot(headingTo(cue, pocket), 3.0));
  EXPECT_TRUE(r.verdict.legal());
  ASSERT_TRUE(r.verdict.winner);
  EXPECT_EQ(*r.verdict.winner, Player::A);
  EXPECT_TRUE(match.rack().over());
  EXPECT_THROW(match.play(shot(0.0, 1.0)), IllegalAction);
}

TEST(MatchThroughPhysics, BreakPushOutAndPass) {
  MatchSetup setup;
  setup.seed = 7;
  Match match(setup);
  EXPECT_TRUE(match.cueBehindHeadString());
  EXPECT_THROW(match.play(shot(0.0, 10.0, Vec2{0.0, 0.0})), IllegalAction);  // not behind
  const TurnRecord brk = match.play(shot(0.0, 10.0));
  EXPECT_TRUE(brk.verdict.legal());
  const Player pusher = brk.verdict.next;
  ASSERT_TRUE(match.rack().pushOutAvailable());
  TurnInput push = shot(90.0, 0.4);
  push.kind = TurnInput::Kind::PushOut;
  const TurnRecord p = match.play(push);
  EXPECT_EQ(p.shooter, pusher);
  EXPECT_TRUE(p.verdict.legal());
  EXPECT_TRUE(p.verdict.awaiting_decision);
  EXPECT_THROW(match.play(shot(0.0, 1.0)), IllegalAction);  // the opponent must decide first
  TurnInput pass;
  pass.kind = TurnInput::Kind::Decision;
  pass.shoot = false;
  const TurnRecord d = match.play(pass);
  EXPECT_EQ(d.shooter, nineball::rules::other(pusher));
  EXPECT_EQ(d.verdict.next, pusher);
  EXPECT_EQ(match.rack().shooter(), pusher);
  EXPECT_THROW(match.play(push), IllegalAction);  // no second push-out
}

TEST(MatchThroughPhysics, ThreeFoulsInARow) {
  // Every turn sends the cue ball across the table, away from the object balls: no contact.
  Match match(layout(
      {BallState::at(0, {-0.8, 0.0}), BallState::at(1, {0.6, 0.0}), BallState::at(9, {0.9, 0.3})}));
  const Foul expected[] = {Foul::NoContact, Foul::NoContact, Foul::NoContact, Foul::NoContact,
                           Foul::ThreeFouls};
  Player shooter = Player::A;
  for (int i = 0; i < 5; ++i) {
    const std::optional<Vec2> cue = i == 0 ? std::nullopt : std::optional<Vec2>(Vec2{-0.8, 0.0});
    const TurnRecord r = match.play(shot(90.0, 0.8, cue));
    EXPECT_EQ(r.shooter, shooter) << i;
    EXPECT_EQ(r.verdict.foul, expected[i]) << i;
    shooter = nineball::rules::other(shooter);
  }
  ASSERT_TRUE(match.rack().winner());
  EXPECT_EQ(*match.rack().winner(), Player::B);
}

TEST(MatchThroughPhysics, PaperScratchReturnsTheCueBallToTheHeadSpot) {
  const InLine line = inLineWithPocket({0.4, 0.0}, 1, 2, 2.0);
  MatchSetup setup = layout(line.balls, RuleSet::Paper);
  setup.physics.ball_restitution = 0.0;
  Match match(setup);
  const TurnRecord r = match.play(line.shot);
  EXPECT_EQ(r.verdict.foul, Foul::Scratch);
  EXPECT_FALSE(r.verdict.ball_in_hand);
  const BallState cue_after = match.balls()[0];
  EXPECT_FALSE(cue_after.pocket);
  EXPECT_DOUBLE_EQ(cue_after.pos.x, match.world().table().headStringX());
  EXPECT_FALSE(match.cueInHand());
}

TEST(MatchThroughPhysics, NineOnAFoulIsSpottedOnTheFootSpot) {
  // Wrong ball first sends the 9 into the pocket: it comes back to the foot spot.
  const InLine line = inLineWithPocket({0.3, 0.0}, 9, 1, 2.0);
  Match match(layout(line.balls));
  const TurnRecord r = match.play(line.shot);
  EXPECT_EQ(r.verdict.foul, Foul::WrongBallFirst);
  EXPECT_EQ(r.verdict.to_spot, std::vector<int>{9});
  EXPECT_FALSE(r.verdict.winner);
  for (const BallState& b : match.balls()) {
    if (b.id != 9) continue;
    EXPECT_FALSE(b.pocket);
    // On the foot spot, or behind it on the long axis if the cue ball sits there.
    EXPECT_GE(b.pos.x, match.world().table().footSpot().x - 1e-12);
    EXPECT_NEAR(b.pos.y, 0.0, 1e-12);
  }
}

namespace {

// step.max_time limits each shot, not the match: the world's clock runs on from shot to shot,
// and shots of 4.4 s under a 10 s limit all run to rest.
TEST(Match, MaxTimeIsPerShotNotPerMatch) {
  MatchSetup s = layout({BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.9, 0.45}),
                         BallState::at(9, {0.9, -0.45})});
  s.step.max_time = 10.0;
  Match m(s);
  for (double heading : {90.0, -90.0, 90.0, -90.0}) {
    const double before = m.world().time();
    m.play(shot(heading, 1.0));
    EXPECT_TRUE(m.world().atRest()) << "at " << m.world().time() << " s";
    EXPECT_GT(m.world().time() - before, 3.0);
  }
  EXPECT_GT(m.world().time(), 10.0);
}

// A shot the window steps frame by frame ends where play() ends it, bit for bit: the same
// steps, spin and clock included.
TEST(Match, SteppingAShotEndsWhereAWholeTurnEnds) {
  const auto setup = layout({BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.3, 0.05})});
  TurnInput t = shot(2.0, 3.0);
  t.shot.tip = {0.3, -0.2};  // side spin: the balls still turn when they stop travelling
  Match whole(setup);
  whole.play(t);
  Match stepped(setup);
  stepped.beginShot(t);
  int steps = 0;
  while (!stepped.stepShot()) ++steps;
  stepped.finishShot();
  EXPECT_GT(steps, 60);
  EXPECT_EQ(stepped.world().time(), whole.world().time());
  const auto a = whole.balls();
  const auto b = stepped.balls();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].pos.x, b[i].pos.x);
    EXPECT_EQ(a[i].pos.y, b[i].pos.y);
    EXPECT_EQ(a[i].w.z, b[i].w.z);
  }
}

}  // namespace
