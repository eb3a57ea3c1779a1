// A script's race to N racks: the racks after the first racked from seed + n and opened as the
// break order says, the racks won counted, the match over at N, and the printed turns of the
// whole match played again as a script end the same.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "io/match_json.hpp"
#include "io/match_play.hpp"
#include "support/computer_race.hpp"

namespace nineball::io {
namespace {

using nlohmann::ordered_json;

MatchPlayed play(const ordered_json& script) {
  const MatchScriptResult parsed = parseMatchScript(script.dump());
  if (const auto* e = std::get_if<ParseError>(&parsed)) {
    ADD_FAILURE() << e->message;
    return {};
  }
  return playMatchScript(std::get<MatchScript>(parsed));
}

std::string refusal(const ordered_json& script) {
  const MatchScriptResult parsed = parseMatchScript(script.dump());
  const auto* e = std::get_if<ParseError>(&parsed);
  return e ? e->message : "accepted";
}

ordered_json computerRace(const char* game, int race_to, const char* breaks, int seed) {
  return {{"game", game},
          {"seed", seed},
          {"race_to", race_to},
          {"breaks", breaks},
          {"players", {{"A", "ai:pro"}, {"B", "ai:pro"}}}};
}

TEST(MatchRace, RacksUntilOneSideWinsTheRaceAlternatingTheBreak) {
  const MatchPlayed played = play(computerRace("nine-ball", 2, "alternate", 3));
  ASSERT_EQ(played.outcome, MatchPlayed::Outcome::Done) << played.why;
  const ordered_json& doc = played.doc;
  EXPECT_EQ(doc.at("race_to"), 2);
  const int won_a = doc.at("racks_won").at("A"), won_b = doc.at("racks_won").at("B");
  EXPECT_EQ(std::max(won_a, won_b), 2);
  EXPECT_EQ(doc.at("winner"), won_a == 2 ? "A" : "B");
  const ordered_json& racks = doc.at("racks");
  ASSERT_EQ(racks.size(), static_cast<std::size_t>(won_a + won_b));
  std::size_t turns = 0;
  for (std::size_t i = 0; i < racks.size(); ++i) {
    EXPECT_EQ(racks[i].at("rack"), i);
    EXPECT_EQ(racks[i].at("seed"), 3 + i);
    EXPECT_EQ(racks[i].at("breaker"), i % 2 == 0 ? "A" : "B");
    turns += racks[i].at("turns").get<std::size_t>();
  }
  ASSERT_EQ(doc.at("turns").size(), turns);
  // Each rack's first turn is its break, played by its breaker.
  std::size_t first = 0;
  for (const auto& rack : racks) {
    EXPECT_EQ(doc.at("turns")[first].at("rack"), rack.at("rack"));
    EXPECT_EQ(doc.at("turns")[first].at("shooter"), rack.at("breaker"));
    first += rack.at("turns").get<std::size_t>();
  }
}

TEST(MatchRace, TheWinnerOfARackBreaksTheNextWhenTheBreaksSaySo) {
  // Seed 1: A wins the first rack and breaks the second (alternate breaks would give it to B),
  // B wins that and breaks the third.
  const MatchPlayed played = play(computerRace("ten-ball", 3, "winner", 1));
  ASSERT_EQ(played.outcome, MatchPlayed::Outcome::Done) << played.why;
  const ordered_json& racks = played.doc.at("racks");
  ASSERT_GE(racks.size(), 3u);
  EXPECT_EQ(racks[0].at("breaker"), "A");
  int breaks_by_b = 0;
  for (std::size_t i = 1; i < racks.size(); ++i) {
    EXPECT_EQ(racks[i].at("breaker"), racks[i - 1].at("winner"));
    breaks_by_b += racks[i].at("breaker") == "B" ? 1 : 0;
  }
  EXPECT_GT(breaks_by_b, 0);
  EXPECT_EQ(racks[1].at("breaker"), "A");
}

TEST(MatchRace, TheWholeMatchsTurnsPlayItAgainAsAScript) {
  for (const char* game : {"nine-ball", "eight-ball"}) {
    SCOPED_TRACE(game);
    ordered_json script = computerRace(game, 2, "winner", 2);
    const MatchPlayed computer = play(script);
    ASSERT_EQ(computer.outcome, MatchPlayed::Outcome::Done) << computer.why;
    script.erase("players");
    script["turns"] = test::scriptTurns(computer.doc);
    const MatchPlayed again = play(script);
    ASSERT_EQ(again.outcome, MatchPlayed::Outcome::Done) << again.why;
    EXPECT_EQ(again.turns, computer.turns);
    EXPECT_EQ(test::judged(again.doc).dump(), test::judged(computer.doc).dump());
    // A turn after the race is won is refused, as a shot after a rack's end is.
    script["turns"].push_back({{"heading_deg", 0}, {"speed", 2}});
    const MatchPlayed beyond = play(script);
    EXPECT_EQ(beyond.outcome, MatchPlayed::Outcome::BadTurn);
    EXPECT_EQ(beyond.why, "turns[" + std::to_string(computer.turns) + "]: the match is over");
  }
}

TEST(MatchRace, AScriptWithoutARacePlaysOneRackAsBefore) {
  ordered_json script = computerRace("nine-ball", 1, "alternate", 3);
  script.erase("race_to");
  script.erase("breaks");
  const MatchPlayed played = play(script);
  ASSERT_EQ(played.outcome, MatchPlayed::Outcome::Done) << played.why;
  EXPECT_FALSE(played.doc.contains("racks"));
  EXPECT_FALSE(played.doc.contains("race_to"));
  EXPECT_FALSE(played.doc.at("turns")[0].contains("rack"));
}

TEST(MatchRace, ARaceTheGameDoesNotPlayIsRefusedByName) {
  EXPECT_EQ(refusal({{"game", "three-cushion"}, {"race_to", 3}, {"turns", ordered_json::array()}}),
            "race_to: three-cushion is one game played to a number of points (\"points\"), not "
            "a race of racks");
  EXPECT_EQ(refusal({{"race_to", 0}, {"turns", ordered_json::array()}}).rfind("race_to: ", 0), 0u);
  EXPECT_EQ(refusal({{"race_to", 100}, {"turns", ordered_json::array()}}).rfind("race_to: ", 0),
            0u);
  EXPECT_EQ(refusal({{"breaks", "winner"}, {"turns", ordered_json::array()}}),
            "breaks: who breaks the next rack is for a race (\"race_to\")");
  EXPECT_EQ(refusal({{"race_to", 2}, {"breaks", "loser"}, {"turns", ordered_json::array()}}),
            "breaks: unknown order \"loser\" (expected alternate or winner)");
}

}  // namespace
}  // namespace nineball::io
