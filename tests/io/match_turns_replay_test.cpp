// The turns a `nineball match` result prints replay their rack exactly: the computer's racks,
// with fouls and ball in hand, turned into a script of plain turns (the shot's heading_rad,
// speed, tip and elevation_rad, the cue ball's place, the call, the push-out, the decision)
// and played again end the same, turn for turn and ball for ball.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "io/match_json.hpp"
#include "io/match_play.hpp"
#include "support/computer_race.hpp"

namespace nineball::io {
namespace {

using nlohmann::ordered_json;

MatchPlayed play(const std::string& text) {
  const MatchScriptResult parsed = parseMatchScript(text);
  if (const auto* e = std::get_if<ParseError>(&parsed)) {
    ADD_FAILURE() << e->message;
    return {};
  }
  return playMatchScript(std::get<MatchScript>(parsed));
}

TEST(MatchTurnsReplay, ComputerRacksWithFoulsAndBallInHandReplayExactly) {
  int fouls = 0, in_hand = 0, racks = 0;
  for (const char* game : {"nine-ball", "eight-ball", "ten-ball"}) {
    for (int seed = 1; seed <= 2; ++seed) {
      SCOPED_TRACE(std::string(game) + " seed " + std::to_string(seed));
      ordered_json script{
          {"game", game}, {"seed", seed}, {"players", {{"A", "ai:beginner"}, {"B", "ai:casual"}}}};
      const MatchPlayed computer = play(script.dump());
      ASSERT_EQ(computer.outcome, MatchPlayed::Outcome::Done) << computer.why;
      script.erase("players");
      script["turns"] = test::scriptTurns(computer.doc);
      const MatchPlayed again = play(script.dump());
      ASSERT_EQ(again.outcome, MatchPlayed::Outcome::Done) << again.why;
      EXPECT_EQ(again.turns, computer.turns);
      EXPECT_EQ(test::judged(again.doc).dump(), test::judged(computer.doc).dump());
      ++racks;
      for (const auto& t : computer.doc.at("turns")) {
        fouls += t.at("result") == "foul" ? 1 : 0;
        in_hand += t.at("ball_in_hand").get<bool>() ? 1 : 0;
      }
    }
  }
  // The racks tried hold what the replay must carry: fouls and the cue ball placed by hand.
  EXPECT_EQ(racks, 6);
  EXPECT_GT(fouls, 0);
  EXPECT_GT(in_hand, 0);
}

TEST(MatchTurnsReplay, AHeadingIsGivenInDegreesOrRadiansNotBoth) {
  const MatchScriptResult both = parseMatchScript(
      R"({"turns": [{"heading_deg": 0, "heading_rad": 0, "speed": 2, "cue": [-0.7, 0]}]})");
  ASSERT_TRUE(std::holds_alternative<ParseError>(both));
  EXPECT_NE(std::get<ParseError>(both).message.find("not both"), std::string::npos);
  const MatchScriptResult rad = parseMatchScript(
      R"({"turns": [{"heading_rad": 0.1234567890123456789, "speed": 2, "cue": [-0.7, 0]}]})");
  ASSERT_TRUE(std::holds_alternative<MatchScript>(rad));
  EXPECT_EQ(std::get<MatchScript>(rad).turns.at(0).shot.heading_rad, 0.1234567890123456789);
}

}  // namespace
}  // namespace nineball::io
