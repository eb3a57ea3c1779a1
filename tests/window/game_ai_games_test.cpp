// The computer opponent in eight-ball and ten-ball, headless: its call and its push-out are
// made in the session as a person's would be (shown, then played), it answers every pending
// decision, and the planner's own turns go through in both games.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "window/computer_player.hpp"
#include "window/frame_builder.hpp"
#include "window/game_rolling.hpp"
#include "window/game_session.hpp"

namespace nineball::window {
namespace {

constexpr double kGamesFrame = 1.0 / 30.0;
using Stage = ComputerPlayer::Stage;

// Runs the computer's frames until `stage` (true), or until its turn is over (false).
bool runUntil(ComputerPlayer& c, GameSession& s, Stage stage) {
  for (int frame = 0; frame < 30 * 30 && c.controls(s); ++frame) {
    c.update(s, kGamesFrame);
    if (c.stage() == stage) return true;
  }
  return false;
}

// Runs the computer's frames until its turn is over; what the status line said on the way.
std::set<std::string> finishTurn(ComputerPlayer& c, GameSession& s) {
  std::set<std::string> said;
  for (int frame = 0; frame < 30 * 30 && c.controls(s); ++frame) {
    c.update(s, kGamesFrame);
    if (c.controls(s)) said.insert(c.status(s));
  }
  return said;
}

// The computer always answers with `move`, whatever the position.
void thinkAlways(ComputerPlayer& c, const ComputerMove& move) {
  c.setWaitForPlans(true);
  c.setThinker([move](ai::Planner&, const ai::PlanInput&, bool) { return move; });
}

// Ten-ball from a layout: Player 1 calls the obvious shot and fouls on the 3 (the 1 is on),
// so the computer comes to the table with the cue ball in hand and a call due.
GameSession tenBallForTheComputer() {
  MatchSetup setup;
  setup.game = rules::Game::TenBall;
  setup.balls = {BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.3, 0.4}),
                 BallState::at(3, {0.0, 0.0}), BallState::at(10, {0.8, -0.3})};
  return GameSession(setup);
}

TEST(ComputerGames, DescribePlanSaysThePushOutTheFirstBallAndTheCall) {
  ai::Plan push;
  push.kind = ai::ShotKind::PushOut;
  push.turn.kind = TurnInput::Kind::PushOut;
  EXPECT_EQ(describePlan(push, 1), "push out");

  ai::Plan safe;  // eight-ball: the plan's first ball, not the lowest legal one
  safe.kind = ai::ShotKind::Safety;
  safe.first = 11;
  EXPECT_EQ(describePlan(safe, 9), "play safe on the 11");
  safe.first = 0;
  EXPECT_EQ(describePlan(safe, 9), "play safe on the 9");

  ai::Plan eight;
  eight.kind = ai::ShotKind::Pot;
  eight.target = 8;
  eight.first = 8;
  eight.pocket = PocketId::TopRight;
  eight.turn.call = rules::Call{8, PocketId::TopRight};
  EXPECT_EQ(describePlan(eight, 8),
            "pot the 8 in the " + std::string(pocketName(PocketId::TopRight)) + " pocket (called)");

  ai::Plan ten;  // a ten-ball safety calls the ball on into the pocket nearest it
  ten.kind = ai::ShotKind::Safety;
  ten.first = 3;
  ten.turn.call = rules::Call{3, PocketId::BottomSide};
  EXPECT_EQ(describePlan(ten, 3), "play safe on the 3 (called: the 3 in the " +
                                      std::string(pocketName(PocketId::BottomSide)) + " pocket)");
}

TEST(ComputerGames, TheComputersCallIsMadeInTheSessionShownAndPlayed) {
  GameSession s = tenBallForTheComputer();
  Seats seats(1);
  ComputerPlayer& c = seats.computer();
  c.setOpponent(s, ComputerSeat{ai::Level::Casual});
  ASSERT_TRUE(s.callRequired());
  s.setHeading(0.0);
  s.setSpeed(1.5);
  s.callObvious();
  ASSERT_TRUE(s.shoot()) << s.message();
  ASSERT_TRUE(roll(s, kGamesFrame));
  ASSERT_TRUE(c.controls(s)) << s.message();
  ASSERT_TRUE(s.callRequired());

  ComputerMove move;
  move.turn.shot.heading_rad = 0.3;
  move.turn.shot.speed = 1.5;
  move.turn.call = rules::Call{1, PocketId::TopRight};
  thinkAlways(c, move);
  ASSERT_TRUE(runUntil(c, s, Stage::Cueing));
  EXPECT_EQ(s.call(), move.turn.call);
  const render::Frame f = buildFrame(s, {}, seats);
  ASSERT_TRUE(f.call) << "the computer's call is drawn on the table";
  EXPECT_TRUE(f.call->pocket);

  finishTurn(c, s);
  ASSERT_EQ(s.phase(), Phase::Rolling) << s.message();
  EXPECT_EQ(s.rackTurns().back().kind, TurnInput::Kind::Shot);
  EXPECT_EQ(s.rackTurns().back().call, move.turn.call);
}

TEST(ComputerGames, AShotWithoutTheCallDueIsCalledTheObviousWay) {
  GameSession s = tenBallForTheComputer();
  ComputerPlayer c(1);
  c.setOpponent(s, ComputerSeat{ai::Level::Casual});
  s.setHeading(0.0);
  s.setSpeed(1.5);
  s.callObvious();
  ASSERT_TRUE(s.shoot()) << s.message();
  ASSERT_TRUE(roll(s, kGamesFrame));
  ASSERT_TRUE(c.controls(s));
  ComputerMove move;  // the planner forgot the call: the window must not get stuck on it
  move.turn.shot.heading_rad = 0.3;
  move.turn.shot.speed = 1.5;
  thinkAlways(c, move);
  ASSERT_TRUE(runUntil(c, s, Stage::Cueing));
  EXPECT_TRUE(s.call().has_value());  // called once aimed, shown while the cue goes back
  finishTurn(c, s);
  ASSERT_EQ(s.phase(), Phase::Rolling) << s.message();
  EXPECT_TRUE(s.rackTurns().back().call.has_value());
  EXPECT_EQ(s.rackTurns().back().shot.heading_rad, 0.3);  // its own shot, not the fallback's
}

TEST(ComputerGames, TheComputersPushOutIsDeclaredAndPlayedAsOne) {
  // The computer breaks (the rematch gives it the break); the seeded rack drops a ball at
  // 10 m/s from the head spot, so it may push out next.
  GameSession s{MatchSetup{}};
  ComputerPlayer c(1);
  c.setOpponent(s, ComputerSeat{ai::Level::Casual});
  s.rematch();
  ASSERT_TRUE(c.controls(s));
  c.setWaitForPlans(true);
  c.setThinker([](ai::Planner&, const ai::PlanInput& in, bool) {
    ComputerMove m;
    m.turn.kind = in.rack.isBreak() ? TurnInput::Kind::Shot : TurnInput::Kind::PushOut;
    m.turn.shot.heading_rad = 0.0;
    m.turn.shot.speed = in.rack.isBreak() ? GameSession::kBreakSpeed : 0.5;
    ai::Plan plan;
    plan.kind = in.rack.isBreak() ? ai::ShotKind::Break : ai::ShotKind::PushOut;
    plan.turn = m.turn;
    m.plan = plan;
    return m;
  });
  finishTurn(c, s);
  ASSERT_TRUE(roll(s, kGamesFrame));
  ASSERT_EQ(s.seatToMove(), ComputerPlayer::kSeat) << s.message();
  ASSERT_TRUE(s.pushOutAvailable());

  ASSERT_TRUE(runUntil(c, s, Stage::Aiming));
  EXPECT_TRUE(s.pushOutDeclared());
  EXPECT_EQ(c.status(s), "Computer pushes out");
  finishTurn(c, s);
  ASSERT_EQ(s.phase(), Phase::Rolling) << s.message();
  EXPECT_EQ(s.rackTurns().back().kind, TurnInput::Kind::PushOut);
  ASSERT_TRUE(roll(s, kGamesFrame));
  EXPECT_EQ(s.phase(), Phase::PushOutChoice);
  EXPECT_EQ(s.seatToMove(), 0);
  EXPECT_NE(s.message().find("Computer pushed out"), std::string::npos) << s.message();
}

// Eight-ball: Player 1's soft break is illegal, and the computer chooses.
GameSession illegalEightBallBreak(ComputerPlayer& c) {
  MatchSetup setup;
  setup.game = rules::Game::EightBall;
  GameSession s(setup);
  c.setOpponent(s, ComputerSeat{ai::Level::Casual});
  s.setSpeed(0.5);
  EXPECT_TRUE(s.shoot()) << s.message();
  EXPECT_TRUE(roll(s, kGamesFrame));
  return s;
}

TEST(ComputerGames, TheComputerReracksAfterAnIllegalBreakAndBreaks) {
  Seats seats(1);
  ComputerPlayer& c = seats.computer();
  GameSession s = illegalEightBallBreak(c);
  ASSERT_EQ(s.phase(), Phase::PushOutChoice) << s.message();
  ASSERT_EQ(s.match().rack().pendingDecision(), rules::Decision::RerackOrPlayOn);
  ASSERT_TRUE(c.controls(s));
  ComputerMove rerack;
  rerack.turn.kind = TurnInput::Kind::Decision;
  rerack.turn.shoot = false;
  thinkAlways(c, rerack);
  c.update(s, kGamesFrame);
  ASSERT_EQ(c.stage(), Stage::Thinking);
  EXPECT_EQ(c.status(s), "Computer thinking: play on or re-rack?");
  const render::Frame f = buildFrame(s, {}, seats);
  EXPECT_TRUE(f.hud.button_left.empty());  // no buttons for the human to press
  for (int frame = 0; frame < 30 * 30 && s.phase() == Phase::PushOutChoice; ++frame) {
    c.update(s, kGamesFrame);
  }
  EXPECT_NE(s.message().find("Computer has the balls re-racked and breaks"), std::string::npos)
      << s.message();
  EXPECT_TRUE(s.match().rack().isBreak());
  EXPECT_EQ(s.seatToMove(), ComputerPlayer::kSeat);
  EXPECT_TRUE(s.pocketedThisRack().empty());
  EXPECT_TRUE(c.controls(s));  // and it breaks
}

TEST(ComputerGames, ThePlannerAnswersTheIllegalBreak) {
  ComputerPlayer c(2);
  GameSession s = illegalEightBallBreak(c);
  ASSERT_EQ(s.phase(), Phase::PushOutChoice) << s.message();
  c.setWaitForPlans(true);
  for (int frame = 0; frame < 30 * 30 && s.phase() == Phase::PushOutChoice; ++frame) {
    c.update(s, kGamesFrame);
  }
  const bool on = s.message().find("Computer plays the table as it lies") != std::string::npos;
  const bool again = s.message().find("Computer has the balls re-racked") != std::string::npos;
  EXPECT_TRUE(on || again) << s.message();
}

// A few turns of each game with the real planner: every computer turn is played (a shot
// struck or a decision taken), none left to the person for want of a call.
void playSomeTurns(rules::Game game) {
  SCOPED_TRACE(rules::gameName(game));
  MatchSetup setup;
  setup.game = game;
  GameSession s(setup);
  ComputerPlayer c(5);
  c.setOpponent(s, ComputerSeat{ai::Level::Casual});
  c.setWaitForPlans(true);
  int computer_turns = 0;
  bool planned = false;
  for (int turn = 0; turn < 40 && computer_turns < 3 && s.phase() != Phase::GameOver; ++turn) {
    if (c.controls(s)) {
      for (const std::string& line : finishTurn(c, s)) {
        planned = planned || line.rfind("Computer: ", 0) == 0;  // not the fallback's words
      }
      ASSERT_FALSE(c.controls(s)) << "the computer's turn never ended: " << s.message();
      ASSERT_EQ(s.message().find("cannot play"), std::string::npos) << s.message();
      ++computer_turns;
    } else if (s.phase() == Phase::PushOutChoice) {
      s.decide(true);
    } else {
      if (s.callRequired()) s.callObvious();
      s.setSpeed(s.match().rack().isBreak() ? GameSession::kBreakSpeed : 2.0);
      ASSERT_TRUE(s.shoot()) << s.message();
    }
    if (s.phase() == Phase::Rolling) {
      ASSERT_TRUE(roll(s, kGamesFrame));
    }
  }
  EXPECT_GT(computer_turns, 0);
  EXPECT_TRUE(planned) << "the planner's own shot was never shown";
}

TEST(ComputerGames, ThePlannerPlaysEightBallTurns) {
  playSomeTurns(rules::Game::EightBall);
}

TEST(ComputerGames, ThePlannerPlaysTenBallTurns) {
  playSomeTurns(rules::Game::TenBall);
}

}  // namespace
}  // namespace nineball::window
