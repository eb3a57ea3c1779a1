// WPBSA's jump shot: the balls the cue ball flew over before it first touched one, from the
// events' places; and the snooker foul it makes in a match, played through the physics.
#include "play/jump_shot.hpp"

#include <gtest/gtest.h>

#include "nineball/match.hpp"

namespace nineball {
namespace {

constexpr double kJumpShotR = 0.028575;
constexpr double kJumpShotDeg = 3.14159265358979323846 / 180.0;

Event flightEvent(EventType type, int a, Vec2 p, int b = -1) {
  Event e;
  e.type = type;
  e.a = a;
  e.b = b;
  e.at = p;
  return e;
}

TEST(JumpShot, ABallUnderTheFlightAndLandedBeyondIsJumpedOver) {
  const std::vector<BallState> before = {
      BallState::at(0, {0.0, 0.0}), BallState::at(2, {0.3, 0.04}), BallState::at(3, {0.3, 0.06}),
      BallState::at(1, {0.9, 0.0})};
  const std::vector<Event> events = {flightEvent(EventType::Airborne, 0, {0.0, 0.0}),
                                     flightEvent(EventType::Land, 0, {0.6, 0.0}),
                                     flightEvent(EventType::BallBall, 0, {}, 1)};
  // The 2 lies within 2R of the flight's line (0.04 < 0.05715), the 3 beyond it.
  EXPECT_EQ(play::ballsJumpedOver(events, before, kJumpShotR), std::vector<int>{2});
}

TEST(JumpShot, NoneAfterTheFirstContactNorBeyondTheLanding) {
  const std::vector<BallState> before = {BallState::at(0, {0.0, 0.0}), BallState::at(2, {0.3, 0.0}),
                                         BallState::at(4, {0.8, 0.0})};
  // Touched the 2 in the air: that contact is its first, whatever it flies over after it.
  EXPECT_TRUE(play::ballsJumpedOver({flightEvent(EventType::Airborne, 0, {0.0, 0.0}),
                                     flightEvent(EventType::BallBall, 0, {}, 2),
                                     flightEvent(EventType::Land, 0, {1.0, 0.0})},
                                    before, kJumpShotR)
                  .empty());
  // Came down short of the 2: nothing jumped.
  EXPECT_TRUE(play::ballsJumpedOver({flightEvent(EventType::Airborne, 0, {0.0, 0.0}),
                                     flightEvent(EventType::Land, 0, {0.25, 0.0})},
                                    before, kJumpShotR)
                  .empty());
  // Another ball's flight is not the cue ball's.
  EXPECT_TRUE(play::ballsJumpedOver({flightEvent(EventType::Airborne, 4, {0.0, 0.0}),
                                     flightEvent(EventType::Land, 4, {0.6, 0.0})},
                                    before, kJumpShotR)
                  .empty());
}

TEST(JumpShot, AFlightBentByACushionIsFollowedFromIt) {
  const std::vector<BallState> before = {BallState::at(0, {0.0, 0.0}),
                                         BallState::at(5, {0.5, 0.3})};
  // Out to a cushion at (0.5, 0.6) and back down towards (0.5, 0.0): over the 5 on the way back.
  EXPECT_EQ(play::ballsJumpedOver({flightEvent(EventType::Airborne, 0, {0.0, 0.0}),
                                   flightEvent(EventType::Cushion, 0, {0.5, 0.6}),
                                   flightEvent(EventType::Land, 0, {0.5, 0.1})},
                                  before, kJumpShotR),
            std::vector<int>{5});
}

MatchSetup jumpSnookerLayout(std::vector<BallState> balls) {
  MatchSetup s;
  s.setGame(rules::Game::Snooker);
  s.balls = std::move(balls);
  return s;
}

TurnInput jumpStroke(double speed, double elevation_deg) {
  TurnInput t;
  t.shot = Shot::withSpeed(0.0, speed);
  t.shot.elevation_rad = elevation_deg * kJumpShotDeg;
  return t;
}

// The first ball the cue ball touched in the last shot.
int cueBallsFirstHit(const Match& m) {
  for (const Event& e : m.world().events()) {
    if (e.type == EventType::BallBall && e.a == kCueBall) return e.b;
    if (e.type == EventType::BallBall && e.b == kCueBall) return e.a;
  }
  return -1;
}

TEST(JumpShot, InSnookerJumpingTheBlueToARedIsAFoul) {
  // The cue ball jumps the blue 0.35 m ahead and comes down short of the red 1.3 m ahead.
  Match m(jumpSnookerLayout({BallState::at(0, {-0.5, 0.0}), BallState::at(19, {-0.15, 0.0}),
                             BallState::at(1, {0.8, 0.0}), BallState::at(21, {1.2, 0.6})}));
  const TurnRecord r = m.play(jumpStroke(4.5, 35.0));
  EXPECT_EQ(r.verdict.foul, rules::Foul::JumpShot) << rules::foulName(r.verdict.foul);
  EXPECT_EQ(cueBallsFirstHit(m), 1) << "it hit the red after the jump";
}

TEST(JumpShot, InSnookerTheSameStrokeWithNothingJumpedIsLegal) {
  Match m(jumpSnookerLayout({BallState::at(0, {-0.5, 0.0}), BallState::at(19, {-0.15, 0.3}),
                             BallState::at(1, {0.8, 0.0}), BallState::at(21, {1.2, 0.6})}));
  const TurnRecord r = m.play(jumpStroke(4.5, 35.0));
  EXPECT_EQ(r.verdict.foul, rules::Foul::None) << rules::foulName(r.verdict.foul);
  EXPECT_EQ(cueBallsFirstHit(m), 1);
}

TEST(JumpShot, InNineBallJumpingABallIsLegal) {
  MatchSetup s;
  s.balls = {BallState::at(0, {-0.5, 0.0}), BallState::at(2, {-0.15, 0.0}),
             BallState::at(1, {0.8, 0.0}), BallState::at(9, {0.9, 0.5})};
  Match m(s);
  const TurnRecord r = m.play(jumpStroke(4.5, 35.0));
  EXPECT_EQ(cueBallsFirstHit(m), 1);
  EXPECT_TRUE(r.verdict.legal()) << rules::foulName(r.verdict.foul);
}

}  // namespace
}  // namespace nineball
