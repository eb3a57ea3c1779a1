// The computer opponent in the game, headless: it plans off the window's thread, shows its
// shot in stages, places the cue ball, answers a push-out, and plays a rack to the end.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <iostream>
#include <set>
#include <stdexcept>
#include <thread>

#include "app/opponent.hpp"
#include "window/computer_player.hpp"
#include "window/frame_builder.hpp"
#include "window/game_input.hpp"
#include "window/game_rolling.hpp"
#include "window/game_session.hpp"

using nineball::BallState;
using nineball::ComputerSeat;
using nineball::HumanSeat;
using nineball::MatchSetup;
using nineball::Seat;
using nineball::TurnInput;
using nineball::Vec2;
using nineball::ai::Level;
using nineball::window::ComputerMove;
using nineball::window::ComputerPlayer;
using nineball::window::GameSession;
using nineball::window::Phase;
using nineball::window::Seats;
using Stage = nineball::window::ComputerPlayer::Stage;

namespace {

constexpr double kAiFrame = 1.0 / 30.0;

// Runs the shot to its end; false if it never ends.
// The test's human: straight at the ball on, hard on the break; plays on after a push-out.
void playHuman(GameSession& s) {
  if (s.phase() == Phase::PushOutChoice) {
    s.decide(true);
    return;
  }
  s.setSpeed(s.match().rack().isBreak() ? GameSession::kBreakSpeed : 2.0);
  ASSERT_TRUE(s.shoot()) << s.message();
}

// Runs the computer's frames until it strikes or decides; the stages it went through.
std::set<Stage> computerTurn(ComputerPlayer& c, GameSession& s) {
  std::set<Stage> seen;
  for (int frame = 0; frame < 30 * 30 && c.controls(s); ++frame) {
    c.update(s, kAiFrame);
    seen.insert(c.stage());
  }
  return seen;
}

MatchSetup layout(std::vector<BallState> balls) {
  MatchSetup setup;
  setup.balls = std::move(balls);
  return setup;
}

// The computer plans as usual, but only once `release` is set: a slow planner on demand.
void holdThinkingUntil(ComputerPlayer& c, std::atomic<bool>& release) {
  c.setThinker([&release](nineball::ai::Planner& p, const nineball::ai::PlanInput& in, bool d) {
    while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return nineball::window::planMove(p, in, d);
  });
}

}  // namespace

TEST(Opponent, NamesAndTheCycleOfTheOKey) {
  using nineball::seatFromName;
  using nineball::app::nextOpponent;
  ASSERT_TRUE(seatFromName("human"));
  EXPECT_EQ(*seatFromName("human"), Seat{HumanSeat{}});
  ASSERT_TRUE(seatFromName("ai:hard"));
  EXPECT_EQ(*seatFromName("ai:hard"), Seat{ComputerSeat{Level::Master}});
  EXPECT_FALSE(seatFromName("ai:grandmaster"));
  EXPECT_EQ(nineball::seatName(ComputerSeat{Level::Club}), "ai:club");
  EXPECT_EQ(nineball::app::opponentLabel(ComputerSeat{Level::Casual}), "vs computer (casual)");
  EXPECT_EQ(nineball::app::opponentLabel(HumanSeat{}), "2 players");
  Seat o;
  for (Seat expected : {Seat{ComputerSeat{Level::Beginner}}, Seat{ComputerSeat{Level::Casual}},
                        Seat{ComputerSeat{Level::Club}}, Seat{ComputerSeat{Level::League}},
                        Seat{ComputerSeat{Level::Advanced}}, Seat{ComputerSeat{Level::Pro}},
                        Seat{ComputerSeat{Level::Master}}, Seat{HumanSeat{}}}) {
    o = nextOpponent(o);
    EXPECT_EQ(o, expected);
  }
}

TEST(ComputerPlayer, OnlyPlayerTwosSeatAndOnlyWhenChosen) {
  GameSession s{MatchSetup{}};
  ComputerPlayer c(1);
  EXPECT_EQ(s.seatName(1), "Player 2");
  c.setOpponent(s, ComputerSeat{Level::Casual});
  EXPECT_EQ(s.seatName(1), "Computer");
  EXPECT_FALSE(c.controls(s));  // Player 1 breaks
  c.update(s, kAiFrame);
  EXPECT_EQ(c.stage(), Stage::Idle);
  c.setOpponent(s, HumanSeat{});
  EXPECT_EQ(s.seatName(1), "Player 2");
}

TEST(ComputerPlayer, ThinksOffTheWindowThreadThenShowsTheShotAndStrikes) {
  // Player 1 misses: ball in hand for the computer, which carries the cue ball to its spot.
  GameSession s(layout({BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.3, 0.4}),
                        BallState::at(3, {0.0, 0.0}), BallState::at(9, {0.8, -0.3})}));
  Seats seats(7);
  ComputerPlayer& c = seats.computer();
  c.setOpponent(s, ComputerSeat{Level::Casual});
  std::atomic<bool> release{false};
  holdThinkingUntil(c, release);
  s.setHeading(0.0);
  s.setSpeed(1.5);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s, kAiFrame));
  ASSERT_EQ(s.seatToMove(), ComputerPlayer::kSeat);
  ASSERT_TRUE(s.cueInHand());
  ASSERT_TRUE(c.controls(s));

  // However long the planner takes, the frames go on and the position stays as it is.
  const Vec2 cue_before = s.cuePosition();
  for (int frame = 0; frame < 60; ++frame) c.update(s, kAiFrame);
  EXPECT_EQ(c.stage(), Stage::Thinking);
  EXPECT_EQ(c.status(s), "Computer thinking...");
  EXPECT_EQ(s.phase(), Phase::Aiming);
  EXPECT_EQ(s.cuePosition(), cue_before);
  const auto thinking = nineball::window::buildFrame(s, {}, seats);
  EXPECT_FALSE(thinking.cue);
  EXPECT_EQ(thinking.hud.status, "Computer thinking...");
  EXPECT_NE(thinking.hud.mode.find("vs computer (casual)"), std::string::npos);

  release = true;
  std::set<Stage> seen;
  double max_pull = 0.0;
  bool guide_while_aiming = false;
  for (int frame = 0; frame < 30 * 30 && c.controls(s); ++frame) {
    c.update(s, kAiFrame);
    if (!c.controls(s)) break;
    seen.insert(c.stage());
    max_pull = std::max(max_pull, c.pull());
    if (c.stage() == Stage::Thinking) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (c.stage() == Stage::Aiming) {
      const auto f = nineball::window::buildFrame(s, {}, seats);
      guide_while_aiming = f.guide && f.cue;
      EXPECT_NE(f.hud.status.find("Computer: "), std::string::npos) << f.hud.status;
    }
  }
  EXPECT_EQ(s.phase(), Phase::Rolling);
  for (Stage st : {Stage::Placing, Stage::Aiming, Stage::Cueing, Stage::Striking}) {
    EXPECT_EQ(seen.count(st), 1u) << static_cast<int>(st);
  }
  EXPECT_TRUE(guide_while_aiming);
  EXPECT_GT(max_pull, 0.0);
  EXPECT_NE(s.cuePosition(), cue_before);
}

TEST(ComputerPlayer, KeysAndClicksDoNotPlayTheComputersTurn) {
  GameSession s(layout(
      {BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.3, 0.4}), BallState::at(3, {0.0, 0.0})}));
  Seats seats(1);
  ComputerPlayer& c = seats.computer();
  c.setOpponent(s, ComputerSeat{Level::Casual});
  s.setHeading(0.0);
  s.setSpeed(1.5);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s, kAiFrame));
  ASSERT_TRUE(c.controls(s));
  nineball::window::UiState ui;
  nineball::window::GameInput input(s, ui, seats);
  const nineball::render::ViewTransform view(s.match().world().table().def, 1280, 800);
  const double heading = s.heading();
  auto tap = [&](sf::Keyboard::Key code) {
    sf::Event key{};
    key.type = sf::Event::KeyPressed;
    key.key.code = code;
    input.handle(key, view);
    key.type = sf::Event::KeyReleased;
    input.handle(key, view);
  };
  for (auto code : {sf::Keyboard::Left, sf::Keyboard::Space, sf::Keyboard::P}) tap(code);
  sf::Event click{};
  click.type = sf::Event::MouseButtonPressed;
  click.mouseButton.button = sf::Mouse::Left;
  click.mouseButton.x = 640;
  click.mouseButton.y = 300;
  input.handle(click, view);
  click.type = sf::Event::MouseButtonReleased;
  input.handle(click, view);
  input.update(1.0);
  EXPECT_EQ(s.phase(), Phase::Aiming);
  EXPECT_EQ(s.heading(), heading);
  EXPECT_FALSE(s.pushOutDeclared());
  // O gives the seat back to a person, who may then play it.
  for (int i = 0; i < 6; ++i) tap(sf::Keyboard::O);  // club ... master, then 2 players
  EXPECT_FALSE(nineball::isComputer(c.opponent()));
  EXPECT_FALSE(c.controls(s));
  tap(sf::Keyboard::Space);
  EXPECT_EQ(s.phase(), Phase::Rolling);
}

TEST(ComputerPlayer, SwitchingOpponentWhileItThinksDropsItsTurn) {
  GameSession s(layout(
      {BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.3, 0.4}), BallState::at(3, {0.0, 0.0})}));
  ComputerPlayer c(1);
  c.setOpponent(s, ComputerSeat{Level::Casual});
  std::atomic<bool> release{false};
  holdThinkingUntil(c, release);
  s.setHeading(0.0);
  s.setSpeed(1.5);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s, kAiFrame));
  c.update(s, kAiFrame);
  ASSERT_EQ(c.stage(), Stage::Thinking);
  // Back to the computer at another level while the dropped plan is still under way: a new
  // planner takes the turn, and the old one's answer is never played.
  c.setOpponent(s, HumanSeat{});
  EXPECT_EQ(c.stage(), Stage::Idle);
  EXPECT_FALSE(c.controls(s));
  c.setOpponent(s, ComputerSeat{Level::Club});
  c.update(s, kAiFrame);
  EXPECT_EQ(c.stage(), Stage::Thinking);
  release = true;
  c.setWaitForPlans(true);
  computerTurn(c, s);
  EXPECT_EQ(s.phase(), Phase::Rolling);
}

TEST(ComputerPlayer, APlannerThatFailsGivesAPlainShotAtTheBallOn) {
  GameSession s(layout(
      {BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.3, 0.4}), BallState::at(3, {0.0, 0.0})}));
  ComputerPlayer c(1);
  c.setOpponent(s, ComputerSeat{Level::Casual});
  c.setWaitForPlans(true);
  c.setThinker([](nineball::ai::Planner&, const nineball::ai::PlanInput&, bool) -> ComputerMove {
    throw std::runtime_error("no plan");
  });
  s.setHeading(0.0);
  s.setSpeed(1.5);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s, kAiFrame));
  ASSERT_TRUE(c.controls(s));
  computerTurn(c, s);
  ASSERT_EQ(s.phase(), Phase::Rolling);
  const Vec2 cue = s.cuePosition();
  EXPECT_NEAR(s.heading(), std::atan2(0.4 - cue.y, 0.3 - cue.x), 1e-9);
  EXPECT_DOUBLE_EQ(s.speed(), 2.0);
}

TEST(ComputerPlayer, AnswersAPushOut) {
  // The break drops a ball (every seeded rack does at 10 m/s from the head spot), so Player 1
  // may push out; the computer then chooses.
  GameSession s{MatchSetup{}};
  Seats seats(3);
  ComputerPlayer& c = seats.computer();
  c.setOpponent(s, ComputerSeat{Level::Casual});
  c.setWaitForPlans(true);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s, kAiFrame));
  ASSERT_EQ(s.seatToMove(), 0) << s.message();
  ASSERT_TRUE(s.pushOutAvailable());
  s.togglePushOut();
  s.setSpeed(0.5);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s, kAiFrame));
  ASSERT_EQ(s.phase(), Phase::PushOutChoice);
  ASSERT_TRUE(c.controls(s));
  const auto f = nineball::window::buildFrame(s, {}, seats);
  EXPECT_TRUE(f.hud.button_left.empty());  // no buttons for the human to press
  // Up to the decision only: a computer that plays on goes on to shoot, and its message with it.
  for (int frame = 0; frame < 30 * 30 && s.phase() == Phase::PushOutChoice; ++frame) {
    c.update(s, kAiFrame);
  }
  const bool played = s.message().find("Computer plays from there") != std::string::npos;
  const bool passed = s.message().find("Computer passes") != std::string::npos;
  EXPECT_TRUE(played || passed) << s.message();
  EXPECT_EQ(s.seatToMove(), played ? 1 : 0);
}

TEST(ComputerPlayer, PlaysARackToTheEndAgainstTheTestsShots) {
  GameSession s{MatchSetup{}};
  ComputerPlayer c(1);
  c.setOpponent(s, ComputerSeat{Level::Casual});
  c.setWaitForPlans(true);
  int computer_shots = 0, human_shots = 0;
  std::set<Stage> seen;
  for (int turn = 0; turn < 300 && s.phase() != Phase::GameOver; ++turn) {
    if (c.controls(s)) {
      const auto stages = computerTurn(c, s);
      seen.insert(stages.begin(), stages.end());
      if (s.phase() == Phase::Rolling) ++computer_shots;
    } else {
      playHuman(s);
      if (HasFatalFailure()) return;
      ++human_shots;
    }
    if (s.phase() == Phase::Rolling) {
      ASSERT_TRUE(roll(s, kAiFrame));
    }
  }
  ASSERT_EQ(s.phase(), Phase::GameOver) << s.message();
  EXPECT_GT(computer_shots, 0);
  EXPECT_EQ(s.racksWon(0) + s.racksWon(1), 1);
  EXPECT_EQ(seen.count(Stage::Aiming), 1u);
  RecordProperty("computer_shots", computer_shots);
  RecordProperty("human_shots", human_shots);
  std::cout << "[ measured ] rack over after " << human_shots << " shots of the test and "
            << computer_shots << " of the computer: " << s.message() << '\n';

  // The rematch: the computer breaks, placing the cue ball behind the head string itself.
  s.rematch();
  ASSERT_TRUE(c.controls(s));
  const auto stages = computerTurn(c, s);
  EXPECT_EQ(s.phase(), Phase::Rolling);
  EXPECT_LE(s.cuePosition().x, s.match().world().table().headStringX());
  EXPECT_TRUE(stages.count(Stage::Aiming));
}
