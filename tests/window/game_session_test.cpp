// The game window's state machine, headless: turns, ball in hand, push-out, game over.
#include "window/game_session.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "window/fixed_step_clock.hpp"
#include "window/frame_builder.hpp"
#include "window/game_rolling.hpp"
#include "window/turn_message.hpp"

using nineball::BallState;
using nineball::MatchSetup;
using nineball::Vec2;
using nineball::window::FixedStepClock;
using nineball::window::GameSession;
using nineball::window::Phase;

namespace {

constexpr double kR = 0.028575;

using nineball::window::roll;

double headingTo(Vec2 from, Vec2 to) {
  return std::atan2(to.y - from.y, to.x - from.x);
}

}  // namespace

TEST(FixedStepClock, StepsWholeStepsAndKeepsTheRestForDrawing) {
  FixedStepClock clock(0.01, 5);
  EXPECT_EQ(clock.advance(0.025), 2);
  EXPECT_NEAR(clock.alpha(), 0.5, 1e-9);
  EXPECT_EQ(clock.advance(0.006), 1);
  EXPECT_NEAR(clock.alpha(), 0.1, 1e-9);
  // A stall is capped and its excess dropped.
  EXPECT_EQ(clock.advance(1.0), 5);
  EXPECT_NEAR(clock.alpha(), 0.0, 1e-9);
}

TEST(GameSession, StartsWithPlayerOneBreakingAtTheOneBall) {
  GameSession s{MatchSetup{}};
  EXPECT_EQ(s.phase(), Phase::Aiming);
  EXPECT_EQ(s.seatToMove(), 0);
  EXPECT_TRUE(s.cueInHand());
  EXPECT_NEAR(s.heading(), 0.0, 1e-12);  // the cue ball and the 1 lie on the long axis
  EXPECT_EQ(s.speed(), GameSession::kBreakSpeed);
  EXPECT_NE(s.status().find("break"), std::string::npos) << s.status();
  const auto guide = s.aimGuide();
  EXPECT_EQ(guide.target, nineball::AimTarget::Ball);
  EXPECT_EQ(guide.ball, 1);
}

TEST(GameSession, TheBreakSpotIsBehindTheHeadString) {
  GameSession s{MatchSetup{}};
  const Vec2 before = s.cuePosition();
  EXPECT_FALSE(s.placeCue({0.2, 0.0}));
  EXPECT_EQ(s.cuePosition(), before);
  EXPECT_NE(s.message().find("head string"), std::string::npos) << s.message();
  EXPECT_TRUE(s.placeCue({-0.9, 0.2}));
  EXPECT_EQ(s.cuePosition(), Vec2(-0.9, 0.2));
}

TEST(GameSession, TheTipStaysInItsUsefulRange) {
  GameSession s{MatchSetup{}};
  s.setTip({0.0, 2.0});
  EXPECT_LE(nineball::length(s.tip()), GameSession::kMaxTip);
  EXPECT_NEAR(s.tip().y, GameSession::kMaxTip, 1e-9);
  s.setPower(1.0);
  EXPECT_EQ(s.speed(), GameSession::kMaxSpeed);
  s.setPower(-1.0);
  EXPECT_EQ(s.speed(), GameSession::kMinSpeed);
}

TEST(GameSession, TheCueRisesToAMasseAndIsLevelAgainForTheNextTurn) {
  MatchSetup setup;
  setup.balls = {BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.3, 0.4}),
                 BallState::at(3, {0.0, 0.0})};
  GameSession s(setup);
  s.setElevation(2.0);  // past the top: held there
  EXPECT_NEAR(s.elevation(), nineball::degToRad(GameSession::kMaxElevationDeg), 1e-12);
  s.setElevation(-1.0);
  EXPECT_EQ(s.elevation(), 0.0);
  s.setElevation(nineball::degToRad(20.0));
  s.setTip({0.4, 0.0});
  s.setHeading(0.0);
  s.setSpeed(1.5);
  ASSERT_TRUE(s.shoot());
  EXPECT_NEAR(s.elevation(), nineball::degToRad(20.0), 1e-12);  // the shot played with it
  ASSERT_TRUE(roll(s));
  EXPECT_EQ(s.elevation(), 0.0);  // a new turn starts with a level cue
}

TEST(GameSession, AWrongBallFirstIsAFoulWithBallInHandForTheOther) {
  MatchSetup setup;
  setup.balls = {BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.3, 0.4}),
                 BallState::at(3, {0.0, 0.0})};
  GameSession s(setup);
  s.setHeading(0.0);
  s.setSpeed(1.5);
  ASSERT_TRUE(s.shoot());
  EXPECT_EQ(s.phase(), Phase::Rolling);
  ASSERT_TRUE(roll(s));
  EXPECT_EQ(s.phase(), Phase::Aiming);
  EXPECT_EQ(s.seatToMove(), 1);
  EXPECT_TRUE(s.cueInHand());
  EXPECT_EQ(s.tone(), nineball::render::Tone::Foul);
  EXPECT_NE(s.message().find("hit the 3 before the 1"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("Ball in hand for Player 2"), std::string::npos) << s.message();
  // In hand anywhere now: in front of the head string too, but not on a ball.
  EXPECT_TRUE(s.placeCue({0.5, -0.3}));
  EXPECT_FALSE(s.placeCue({0.3, 0.4 + kR}));
}

TEST(GameSession, AScratchPutsTheCueBallInHandOnAFreeSpot) {
  // A full, inelastic hit: the cue ball follows the 1 into the top-right pocket.
  MatchSetup setup;
  setup.physics.ball_restitution = 0.0;
  const Vec2 cue{0.6, 0.0}, one{0.9, 0.3};
  setup.balls = {BallState::at(0, cue), BallState::at(1, one), BallState::at(2, {-0.8, -0.3})};
  GameSession s(setup);
  s.setHeading(headingTo(cue, one));
  s.setSpeed(4.0);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  ASSERT_EQ(s.phase(), Phase::Aiming);
  EXPECT_NE(s.message().find("the cue ball went into a pocket"), std::string::npos) << s.message();
  // The 1 went down on the foul: it stays down, the message says so, the tray holds it.
  EXPECT_NE(s.message().find("The 1 went down and stays down."), std::string::npos) << s.message();
  EXPECT_EQ(s.pocketedThisRack(), std::vector<int>{1});
  EXPECT_EQ(s.match().rack().ballOn(), 2);
  EXPECT_TRUE(s.cueInHand());
  EXPECT_FALSE(s.placementProblem(s.cuePosition())) << s.cuePosition().x;
  bool cue_drawn = false;
  for (const BallState& b : s.ballsToDraw()) {
    if (b.id == 0) cue_drawn = !b.pocket;
  }
  EXPECT_TRUE(cue_drawn);
  ASSERT_TRUE(s.shoot());  // from the spot it was given
}

TEST(GameSession, PushOutThenPass) {
  GameSession s{MatchSetup{}};
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  ASSERT_EQ(s.phase(), Phase::Aiming);
  // The break is deterministic and legal: the next shooter is offered the push-out.
  ASSERT_TRUE(s.pushOutAvailable());
  const int pusher = s.seatToMove();
  s.togglePushOut();
  EXPECT_TRUE(s.pushOutDeclared());
  s.setSpeed(0.5);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  ASSERT_EQ(s.phase(), Phase::PushOutChoice);
  EXPECT_EQ(s.seatToMove(), 1 - pusher);
  s.decide(false);
  EXPECT_EQ(s.phase(), Phase::Aiming);
  EXPECT_EQ(s.seatToMove(), pusher);
  EXPECT_NE(s.message().find("passes"), std::string::npos) << s.message();
}

TEST(GameSession, TheNineWinsTheRackAndARematchLetsTheOtherBreak) {
  MatchSetup setup;
  const Vec2 cue{0.2, 0.1}, nine{0.5, -0.1};
  setup.balls = {BallState::at(0, cue), BallState::at(9, nine)};
  GameSession s(setup);
  s.setHeading(nineball::degToRad(-33.69));
  s.setSpeed(3.0);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  ASSERT_EQ(s.phase(), Phase::GameOver);
  EXPECT_EQ(s.racksWon(0), 1);
  EXPECT_EQ(s.tone(), nineball::render::Tone::Win);
  EXPECT_FALSE(s.shoot());
  s.rematch();
  EXPECT_EQ(s.phase(), Phase::Aiming);
  EXPECT_EQ(s.rackNumber(), 2);
  EXPECT_EQ(s.seatToMove(), 1);  // Player 2 breaks the second rack
  EXPECT_EQ(s.match().balls().size(), 10u);
  EXPECT_EQ(s.racksWon(0), 1);
}

TEST(GameSession, DrawsBetweenTheLastTwoSteps) {
  GameSession s{MatchSetup{}};
  ASSERT_TRUE(s.shoot());
  const double dt = s.match().world().stepParams().dt();
  s.advance(dt * 2.5);
  const auto half = s.ballsToDraw();
  const auto now = s.match().balls();
  // Two steps taken, half a step left over: the cue ball is drawn half way between the
  // first and the second step, behind where the physics has it and past its start.
  EXPECT_EQ(s.match().world().steps(), 2);
  EXPECT_LT(half[0].pos.x, now[0].pos.x);
  EXPECT_GT(half[0].pos.x, s.match().world().table().headStringX());
}

TEST(TurnMessage, ListsBalls) {
  EXPECT_EQ(nineball::window::ballList({3}), "the 3");
  EXPECT_EQ(nineball::window::ballList({3, 5}), "the 3 and the 5");
  EXPECT_EQ(nineball::window::ballList({2, 3, 7}), "the 2, the 3 and the 7");
}

TEST(GameSession, PushOutKeyExplainsWhenNoneIsAllowed) {
  MatchSetup setup;
  GameSession s(setup);  // the break: no push-out yet
  s.togglePushOut();
  EXPECT_FALSE(s.pushOutDeclared());
  EXPECT_NE(s.message().find("No push-out now"), std::string::npos) << s.message();
  EXPECT_EQ(s.tone(), nineball::render::Tone::Warning);
}

TEST(GameSession, AScriptCannotGiveASpeedTheCueCannot) {
  MatchSetup setup;
  GameSession s(setup);
  nineball::TurnInput turn;
  turn.shot.speed = GameSession::kMaxSpeed + 0.5;
  EXPECT_THROW(s.playTurn(turn), nineball::IllegalAction);
  turn.shot.speed = GameSession::kMinSpeed / 2.0;
  EXPECT_THROW(s.playTurn(turn), nineball::IllegalAction);
  turn.shot.speed = GameSession::kMaxSpeed;
  EXPECT_NO_THROW(s.playTurn(turn));
}

// Snooker's frames follow one another as racks do, counted per player; in a match of best of
// N the first to ceil(N/2) frames wins it, and the next rematch starts a new match at 0-0.
namespace {

GameSession snookerFrameWonOnTheBlack(int best_of, int won0, int won1) {
  MatchSetup setup;
  setup.setGame(nineball::rules::Game::Snooker);
  // The black alone, straight at the top-right pocket: its pot ends the frame, 7-0.
  setup.balls = {BallState::at(0, {1.40, 0.505}), BallState::at(21, {1.60, 0.705})};
  GameSession s(setup);
  s.setBestOf(best_of);
  s.resumeRack(0, won0, won1);
  s.setHeading(nineball::degToRad(45.0));
  s.setSpeed(2.5);
  EXPECT_TRUE(s.shoot());
  EXPECT_TRUE(roll(s));
  EXPECT_EQ(s.phase(), Phase::GameOver);
  return s;
}

}  // namespace

TEST(GameSession, SnookerFramesCountTowardsAMatchOfBestOfN) {
  GameSession s = snookerFrameWonOnTheBlack(3, 0, 0);
  EXPECT_EQ(s.racksWon(0), 1);
  EXPECT_FALSE(s.matchWinner());
  EXPECT_EQ(s.status(), "Player 1 wins frame 1 (frames 1-0, best of 3). R: next frame");
  s.rematch();
  EXPECT_EQ(s.phase(), Phase::Aiming);
  EXPECT_EQ(s.racksWon(0), 1);               // the match goes on
  EXPECT_GE(s.match().balls().size(), 21u);  // the next frame racked in full

  GameSession won = snookerFrameWonOnTheBlack(3, 1, 1);
  ASSERT_TRUE(won.matchWinner());
  EXPECT_EQ(*won.matchWinner(), 0);
  EXPECT_EQ(won.status(), "Player 1 wins the match 2-1 (best of 3). R: new match");
  won.rematch();
  EXPECT_EQ(won.racksWon(0), 0);  // a new match
  EXPECT_EQ(won.racksWon(1), 0);
  EXPECT_FALSE(won.matchWinner());

  // Without a match length the frames simply add up.
  GameSession open = snookerFrameWonOnTheBlack(0, 4, 0);
  EXPECT_EQ(open.racksWon(0), 5);
  EXPECT_FALSE(open.matchWinner());
}

TEST(GameSession, APocketedBallSinksOutOfSightAfterTheBallsStop) {
  // The picture's clock runs on after the shot, so a ball that dropped as the balls stopped
  // finishes its sinking (BallPainter::kSinkTime) instead of waiting on the lip for the next
  // shot; the next shot starts the clock from the physics' again.
  GameSession s{MatchSetup{}};
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(nineball::window::roll(s));
  const double stopped = s.drawTime();
  for (int frame = 0; frame < 30; ++frame) s.advance(1.0 / 60.0);
  EXPECT_NEAR(s.drawTime() - stopped, 0.5, 1e-9);
  for (int frame = 0; frame < 120; ++frame) s.advance(1.0 / 60.0);
  EXPECT_NEAR(s.drawTime() - stopped, 1.0, 1e-9);  // then it stops: nothing moves at rest
  ASSERT_TRUE(s.shoot());
  s.advance(1.0 / 60.0);
  EXPECT_LT(s.drawTime(), stopped + 0.1);
}

TEST(GameSession, PracticeSaysItsKeysOnceNotInTheStatusLineToo) {
  GameSession s{MatchSetup{}, true};
  nineball::window::UiState ui;
  const nineball::window::Seats seats(1);
  const nineball::render::Frame f = nineball::window::buildFrame(s, ui, seats);
  EXPECT_NE(f.hud.mode.find("U undo"), std::string::npos);
  EXPECT_EQ(f.hud.status.find("U undo"), std::string::npos) << f.hud.status;
  EXPECT_EQ(f.hud.status.find("1-9"), std::string::npos) << f.hud.status;
}
