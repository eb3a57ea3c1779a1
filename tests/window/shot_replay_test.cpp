// The replay of the last shot comes from the physics: it ends exactly where the shot did.
#include "window/shot_replay.hpp"

#include <gtest/gtest.h>

#include "window/game_rolling.hpp"
#include "window/game_session.hpp"

namespace nineball::window {
namespace {

void rollLive(GameSession& s) {
  ASSERT_TRUE(roll(s));
}

int framesToFinish(ShotReplay& r) {
  int frames = 0;
  while (!r.finished() && frames < 60 * 600) {
    r.advance(1.0 / 60.0);
    ++frames;
  }
  return frames;
}

void expectSameBalls(const std::vector<BallState>& a, const std::vector<BallState>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].id, b[i].id);
    EXPECT_EQ(a[i].pocket, b[i].pocket) << a[i].id;
    // Bit for bit: the same simulation, not a recording within some tolerance.
    EXPECT_EQ(a[i].pos.x, b[i].pos.x) << a[i].id;
    EXPECT_EQ(a[i].pos.y, b[i].pos.y) << a[i].id;
  }
}

TEST(ShotReplay, TheBreakReplayedEndsBitForBitWhereItStopped) {
  GameSession s{MatchSetup{}};
  EXPECT_FALSE(s.replayAvailable());
  ASSERT_TRUE(s.shoot());
  rollLive(s);
  ASSERT_NE(s.phase(), Phase::Rolling);
  ASSERT_TRUE(s.replayAvailable());
  ShotReplay replay(s.rackSetup(), s.rackTurns(), 1.0);
  // At the start the balls stand where the break began: the rack, untouched.
  bool racked = false;
  for (const BallState& b : replay.balls()) racked = racked || (b.id == 1 && !b.pocket);
  EXPECT_TRUE(racked);
  const int frames = framesToFinish(replay);
  EXPECT_TRUE(replay.finished());
  expectSameBalls(replay.balls(), s.match().balls());

  ShotReplay slow(s.rackSetup(), s.rackTurns(), GameSession::kSlowReplay);
  const int slow_frames = framesToFinish(slow);
  expectSameBalls(slow.balls(), s.match().balls());
  EXPECT_NEAR(slow_frames, frames / GameSession::kSlowReplay, 2.0);
}

TEST(ShotReplay, ALaterShotIsReplayedAfterTheTurnsBeforeIt) {
  GameSession s{MatchSetup{}};
  ASSERT_TRUE(s.shoot());
  rollLive(s);
  if (s.phase() == Phase::PushOutChoice) s.decide(true);
  ASSERT_EQ(s.phase(), Phase::Aiming);
  s.setSpeed(2.0);
  ASSERT_TRUE(s.shoot());
  rollLive(s);
  ShotReplay replay(s.rackSetup(), s.rackTurns(), 1.0);
  framesToFinish(replay);
  expectSameBalls(replay.balls(), s.match().balls());
}

TEST(ShotReplay, TheSessionShowsTheReplayAndAnyKeyEndsIt) {
  GameSession s{MatchSetup{}};
  ASSERT_TRUE(s.shoot());
  rollLive(s);
  const auto rest = s.ballsToDraw();
  s.startReplay(false);
  ASSERT_TRUE(s.replaying());
  EXPECT_NE(s.status().find("Replay"), std::string::npos);
  s.advance(0.1);
  EXPECT_NE(s.ballsToDraw()[0].pos.x, rest[0].pos.x);  // the cue ball is on its way again
  s.stopReplay();
  EXPECT_FALSE(s.replaying());
  EXPECT_EQ(s.ballsToDraw()[0].pos.x, rest[0].pos.x);
}

}  // namespace
}  // namespace nineball::window
