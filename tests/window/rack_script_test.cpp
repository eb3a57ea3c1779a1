// A rack saved as a match script (F5) plays again headless to the same balls, bit for bit:
// shots with spin and tilt, the cue ball placed in hand, ten-ball's calls and decisions.
#include "window/rack_script.hpp"

#include <gtest/gtest.h>

#include <variant>

#include "io/match_json.hpp"
#include "io/match_play.hpp"
#include "window/game_rolling.hpp"

namespace nineball::window {
namespace {

// Plays the session's rack on: shots at a few headings with spin and tilt, K calling where a
// call is due, every decision answered "play".
void playSome(GameSession& s, int shots) {
  const double headings[] = {0.3, -1.1, 2.0, 0.7, -2.6, 1.4, -0.4, 2.9};
  for (int i = 0; i < shots && s.phase() != Phase::GameOver; ++i) {
    if (s.phase() == Phase::PushOutChoice) {
      s.decide(true);
      continue;
    }
    s.setHeading(headings[i % 8]);
    s.setSpeed(2.345678901 + 0.5 * i);
    s.setTip({0.1234567, -0.2});
    s.setElevation(0.05);
    if (s.callRequired()) s.callObvious();
    ASSERT_TRUE(s.shoot()) << s.message();
    ASSERT_TRUE(roll(s));
  }
}

void expectReplaysExactly(const GameSession& s) {
  const auto script = rackScript(s);
  ASSERT_TRUE(script);
  const io::MatchScriptResult parsed = io::parseMatchScript(script->dump());
  ASSERT_TRUE(std::holds_alternative<io::MatchScript>(parsed))
      << std::get<io::ParseError>(parsed).message;
  const io::MatchPlayed played = io::playMatchScript(std::get<io::MatchScript>(parsed));
  ASSERT_EQ(played.outcome, io::MatchPlayed::Outcome::Done) << played.why;
  EXPECT_EQ(played.turns, s.rackTurns().size());
  const auto& balls = played.doc.at("balls");
  const std::vector<BallState> now = s.match().balls();
  ASSERT_EQ(balls.size(), now.size());
  for (std::size_t i = 0; i < now.size(); ++i) {
    SCOPED_TRACE("ball " + std::to_string(now[i].id));
    EXPECT_EQ(balls[i].at("id").get<int>(), now[i].id);
    if (now[i].pocket) continue;
    EXPECT_EQ(balls[i].at("x").get<double>(), now[i].pos.x);
    EXPECT_EQ(balls[i].at("y").get<double>(), now[i].pos.y);
  }
}

TEST(RackScript, ANineBallRackPlaysAgainToTheBit) {
  MatchSetup setup;
  setup.seed = 11;
  GameSession s(setup);
  ASSERT_TRUE(s.shoot());  // the break
  ASSERT_TRUE(roll(s));
  playSome(s, 6);
  expectReplaysExactly(s);
}

TEST(RackScript, ATenBallRackWithCallsAndDecisionsPlaysAgainToTheBit) {
  MatchSetup setup;
  setup.setGame(rules::Game::TenBall);
  setup.seed = 4;
  GameSession s(setup);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  playSome(s, 8);
  expectReplaysExactly(s);
  const auto script = rackScript(s);
  EXPECT_EQ(script->at("game"), "ten-ball");
}

TEST(RackScript, PracticeHasNoRackToSave) {
  GameSession s(MatchSetup{}, true);
  EXPECT_FALSE(rackScript(s));
}

}  // namespace
}  // namespace nineball::window
