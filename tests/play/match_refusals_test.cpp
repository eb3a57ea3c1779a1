// A match refuses what its game would ignore, by name and in the game's own words: carom on a
// table with pockets, a call in a game that takes none, a push-out where there is none, a
// snooker nomination the rules would not read (a red, a colour while a red is on, a free ball
// when none is due), and a decision nothing waits for.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <variant>

#include "io/match_json.hpp"
#include "nineball/match.hpp"
#include "play/match_turns.hpp"

namespace nineball {
namespace {

using play_test::decision;
using play_test::shot;
using rules::Game;

// The refusal's words (a test failure when `act` is taken).
std::string refusal(const std::function<void()>& act) {
  try {
    act();
  } catch (const IllegalAction& e) {
    return e.what();
  }
  ADD_FAILURE() << "taken without a word";
  return "";
}

MatchSetup gameSetup(Game game, std::optional<std::vector<BallState>> balls = std::nullopt) {
  MatchSetup s;
  s.setGame(game);
  s.balls = std::move(balls);
  return s;
}

TurnInput called(TurnInput t, int ball) {
  t.call = rules::Call{ball, PocketId::TopRight};
  return t;
}

TEST(MatchRefusals, ThreeCushionIsPlayedOnlyOnATableWithoutPockets) {
  MatchSetup s = gameSetup(Game::ThreeCushion);
  s.table = TableDef::nineFoot();
  const std::string why = refusal([&] { Match m(s); });
  EXPECT_NE(why.find("three-cushion is played on a table without pockets"), std::string::npos)
      << why;
  // A script asking for it is refused at its "table" field.
  const io::MatchScriptResult script =
      io::parseMatchScript(R"({"game": "three-cushion", "table": "9ft"})");
  ASSERT_TRUE(std::holds_alternative<io::ParseError>(script));
  const std::string message = std::get<io::ParseError>(script).message;
  EXPECT_EQ(message.rfind("table: ", 0), 0u) << message;
  EXPECT_NE(message.find("without pockets"), std::string::npos) << message;
  // Its own tables are fine.
  s.table = TableDef::caromSmall();
  EXPECT_NO_THROW(Match{s});
}

TEST(MatchRefusals, ACallInAGameThatTakesNoneIsRefusedByName) {
  Match nine(gameSetup(Game::NineBall));
  std::string why = refusal([&] { nine.play(called(shot(0.0, 8.0, Vec2{-0.7, 0.0}), 1)); });
  EXPECT_NE(why.find("nine-ball takes no call"), std::string::npos) << why;
  EXPECT_NE(why.find("eight-ball, ten-ball and snooker"), std::string::npos) << why;
  Match carom(gameSetup(Game::ThreeCushion));
  why = refusal([&] { carom.play(called(shot(0.0, 3.0), 2)); });
  EXPECT_NE(why.find("three-cushion takes no call"), std::string::npos) << why;
}

TEST(MatchRefusals, APushOutWhereTheGameHasNoneSaysSo) {
  Match eight(gameSetup(Game::EightBall));
  TurnInput push = shot(0.0, 8.0, Vec2{-0.7, 0.0});
  push.kind = TurnInput::Kind::PushOut;
  std::string why = refusal([&] { eight.play(push); });
  EXPECT_EQ(why, "eight-ball has no push-out");
  Match snooker(gameSetup(Game::Snooker));
  why = refusal([&] { snooker.play(push); });
  EXPECT_EQ(why, "snooker has no push-out");
}

TEST(MatchRefusals, ADecisionNothingWaitsForIsRefusedInTheGamesOwnWords) {
  Match carom(gameSetup(Game::ThreeCushion));
  std::string why = refusal([&] { carom.play(decision(true)); });
  EXPECT_NE(why.find("three-cushion has no choice between turns"), std::string::npos) << why;
  EXPECT_EQ(why.find("push-out"), std::string::npos) << why;
  Match snooker(gameSetup(Game::Snooker));
  why = refusal([&] { snooker.play(decision(true)); });
  EXPECT_NE(why.find("after a foul"), std::string::npos) << why;
  EXPECT_EQ(why.find("push-out"), std::string::npos) << why;
  Match nine(gameSetup(Game::NineBall));
  why = refusal([&] { nine.play(decision(true)); });
  EXPECT_NE(why.find("push-out"), std::string::npos) << why;
}

// Reds on, no red just potted: the cue ball in the middle, a red and the blue about.
std::vector<BallState> redsOn() {
  return {BallState::at(kCueBall, {0.0, 0.0}), BallState::at(1, {0.8, 0.3}),
          BallState::at(2, {0.8, -0.3}), BallState::at(19, {0.0, 0.5})};
}

TEST(MatchRefusals, SnookerRefusesANominationItsRulesWouldNotRead) {
  Match m(gameSetup(Game::Snooker, redsOn()));
  std::string why = refusal([&] { m.play(called(shot(20.0, 1.0), 19)); });
  EXPECT_NE(why.find("the blue cannot be nominated: a red is on"), std::string::npos) << why;
  EXPECT_NE(why.find("no free ball is due"), std::string::npos) << why;
  why = refusal([&] { m.play(called(shot(20.0, 1.0), 1)); });
  EXPECT_NE(why.find("a red is never nominated"), std::string::npos) << why;
  // Only the colours left, in order: the blue is on, the black may not be nominated.
  Match colours(gameSetup(Game::Snooker, std::vector<BallState>{BallState::at(kCueBall, {0.0, 0.0}),
                                                                BallState::at(19, {0.8, 0.3}),
                                                                BallState::at(21, {0.8, -0.3})}));
  why = refusal([&] { colours.play(called(shot(20.0, 1.0), 21)); });
  EXPECT_NE(why.find("the black cannot be nominated: the colours are taken in order and the "
                     "blue is on"),
            std::string::npos)
      << why;
  EXPECT_NO_THROW(colours.play(called(shot(20.0, 1.0), 19)));
}

}  // namespace
}  // namespace nineball
