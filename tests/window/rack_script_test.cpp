// A rack saved as a match script (F5) plays again headless to the same balls, bit for bit:
// shots with spin and tilt, the cue ball placed in hand, ten-ball's calls and decisions; a
// match of several racks saved whole, its racks broken as the headless race breaks them.
#include "window/rack_script.hpp"

#include <gtest/gtest.h>

#include <variant>

#include "io/match_json.hpp"
#include "io/match_play.hpp"
#include "support/computer_race.hpp"
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
  const auto script = gameScript(s);
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
  const auto script = gameScript(s);
  EXPECT_EQ(script->at("game"), "ten-ball");
}

TEST(RackScript, AWholeRaceSavedFromTheWindowPlaysAgainHeadlessRackForRack) {
  // Seed 1's ten-ball race to 2, winner breaks: A wins the first rack and breaks the second
  // too (in turn, B would), B wins that and breaks the third.
  const test::ComputerRace race = test::computerRace("ten-ball", 2, "winner", 1);
  MatchSetup setup;
  setup.setGame(rules::Game::TenBall);
  setup.seed = 1;
  GameSession s(setup);
  s.setBestOf(3);
  s.setBreaks(BreakOrder::Winner);
  for (const TurnInput& t : race.turns) s.playTurn(t);  // a script's turns go on into each rack
  ASSERT_EQ(s.phase(), Phase::GameOver);
  ASSERT_TRUE(s.matchWinner());
  EXPECT_EQ(s.racksWon(0), race.doc.at("racks_won").at("A").get<int>());
  EXPECT_EQ(s.racksWon(1), race.doc.at("racks_won").at("B").get<int>());
  ASSERT_TRUE(savesMatch(s));
  const auto script = gameScript(s);
  ASSERT_TRUE(script);
  EXPECT_EQ(script->at("race_to"), 2);
  EXPECT_EQ(script->at("breaks"), "winner");
  EXPECT_EQ(script->at("turns").size(), race.turns.size());
  const io::MatchScriptResult parsed = io::parseMatchScript(script->dump());
  ASSERT_TRUE(std::holds_alternative<io::MatchScript>(parsed))
      << std::get<io::ParseError>(parsed).message;
  const io::MatchPlayed again = io::playMatchScript(std::get<io::MatchScript>(parsed));
  ASSERT_EQ(again.outcome, io::MatchPlayed::Outcome::Done) << again.why;
  EXPECT_EQ(again.doc.at("racks").dump(), race.doc.at("racks").dump());
  EXPECT_EQ(again.doc.at("winner"), race.doc.at("winner"));
  EXPECT_EQ(again.doc.at("balls").dump(), race.doc.at("balls").dump());
  // The window's last rack ends on the same balls.
  const std::vector<BallState> now = s.match().balls();
  const auto& balls = again.doc.at("balls");
  ASSERT_EQ(balls.size(), now.size());
  for (std::size_t i = 0; i < now.size(); ++i) {
    if (now[i].pocket) continue;
    EXPECT_EQ(balls[i].at("x").get<double>(), now[i].pos.x);
    EXPECT_EQ(balls[i].at("y").get<double>(), now[i].pos.y);
  }
  // Turns past the race's end are refused, as headless.
  EXPECT_THROW(s.playTurn(race.turns.front()), IllegalAction);
}

TEST(RackScript, ARackAloneIsSavedWhenTheMatchHasNoLength) {
  MatchSetup setup;
  setup.seed = 11;
  GameSession s(setup);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  EXPECT_FALSE(savesMatch(s));
  EXPECT_FALSE(gameScript(s)->contains("race_to"));
  s.setBestOf(3);
  EXPECT_TRUE(savesMatch(s));
  s.setFixedSeats(true);  // online: the host breaks every rack, which no script says
  EXPECT_FALSE(savesMatch(s));
}

TEST(RackScript, AScriptsOwnTableIsKeptAndALayoutOnlyForTheRackItLaidOut) {
  MatchSetup setup;
  setup.seed = 5;
  GameSession s(setup);
  s.setBestOf(3);
  const nlohmann::json own = {{"table", "8ft"},
                              {"balls", {{{"id", 0}, {"x", 0}, {"y", 0}}}},
                              {"seed", 99},
                              {"race_to", 3},
                              {"turns", {1}}};
  const auto match = gameScript(s, own);
  EXPECT_EQ(match->at("table"), "8ft");
  EXPECT_EQ(match->at("seed"), 5);
  EXPECT_EQ(match->at("race_to"), 2);       // the session's race, not the script's
  EXPECT_TRUE(match->contains("balls"));    // the match's first rack is the laid-out one
  EXPECT_TRUE(match->at("turns").empty());  // the session's turns
  s.setBestOf(0);
  const auto rack = gameScript(s, own);
  EXPECT_FALSE(rack->contains("race_to"));
  EXPECT_FALSE(rack->contains("balls"));  // this rack was racked, not laid out
}

TEST(RackScript, PracticeHasNoRackToSave) {
  GameSession s(MatchSetup{}, true);
  EXPECT_FALSE(gameScript(s));
}

}  // namespace
}  // namespace nineball::window
