// Whole games between two computers, held to what must hold of any game instead of pinned turn
// by turn (a pinned story changes whenever the computer's play does, and then proves nothing
// but that it changed): every turn's score adds up by the rules, the innings and averages
// agree, and the result is the same bit for bit on one planner thread as on two.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <variant>

#include "io/match_json.hpp"
#include "io/match_play.hpp"
#include "rules/snooker_balls.hpp"

namespace nineball::io {
namespace {

MatchPlayed play(const std::string& text, int threads) {
  const MatchScriptResult parsed = parseMatchScript(text);
  const auto* script = std::get_if<MatchScript>(&parsed);
  if (script == nullptr) {
    ADD_FAILURE() << "the script is refused: " << text;
    return {};
  }
  return playMatchScript(*script, threads);
}

std::string other(const std::string& player) {
  return player == "A" ? "B" : "A";
}

int pointsOf(const nlohmann::ordered_json& score, const std::string& player) {
  return score[player]["points"].get<int>();
}

// Played on one thread, checked by `check`, and played again on two: the same document.
template <class Check>
void playAndCheck(const std::string& text, Check check) {
  const MatchPlayed one = play(text, 1);
  ASSERT_EQ(one.outcome, MatchPlayed::Outcome::Done) << one.why;
  ASSERT_FALSE(one.doc["partial"].get<bool>());
  check(one.doc);
  EXPECT_EQ(play(text, 2).doc.dump(), one.doc.dump()) << "two planner threads played otherwise";
}

TEST(MatchInvariants, ASnookerFrameBetweenTwoComputersAddsUpStrokeByStroke) {
  playAndCheck(R"({"game": "snooker", "seed": 1,
                   "players": {"A": "ai:advanced", "B": "ai:advanced"}})",
               [](const nlohmann::ordered_json& doc) {
                 nlohmann::ordered_json before = {{"A", {{"points", 0}}}, {"B", {{"points", 0}}}};
                 int fouls = 0, pots = 0;
                 for (std::size_t i = 0; i < doc["turns"].size(); ++i) {
                   const auto& t = doc["turns"][i];
                   const std::string shooter = t["shooter"], them = other(shooter);
                   const auto& after = t["score"];
                   const int gained = pointsOf(after, shooter) - pointsOf(before, shooter);
                   const int given = pointsOf(after, them) - pointsOf(before, them);
                   if (t.contains("decision")) {
                     EXPECT_EQ(gained, 0) << "turn " << i;
                     EXPECT_EQ(given, 0) << "turn " << i;
                   } else if (!t["foul"].is_null()) {
                     ++fouls;
                     const int penalty = t["penalty"];
                     EXPECT_TRUE(penalty >= 4 && penalty <= 7) << "turn " << i << ": " << penalty;
                     EXPECT_EQ(gained, 0) << "turn " << i;
                     EXPECT_EQ(given, penalty) << "turn " << i;
                   } else {
                     EXPECT_EQ(t["penalty"], 0) << "turn " << i;
                     EXPECT_EQ(gained, t["points"].get<int>()) << "turn " << i;
                     EXPECT_EQ(given, 0) << "turn " << i;
                     // A ball potted legally scores no more than it is worth (a free ball
                     // counts as a red), and nothing potted scores nothing.
                     int worth = 0;
                     for (const auto& b : t["pocketed"])
                       worth += rules::snooker::value(b.get<int>());
                     EXPECT_LE(gained, worth) << "turn " << i;
                     EXPECT_EQ(gained > 0, !t["pocketed"].empty()) << "turn " << i;
                     if (gained > 0) ++pots;
                     if (t["winner"].is_null()) {
                       EXPECT_EQ(t["next"], gained > 0 ? shooter : them) << "turn " << i;
                     }
                   }
                   for (const std::string p : {"A", "B"}) {
                     EXPECT_GE(after[p]["high_break"].get<int>(), after[p]["break"].get<int>())
                         << "turn " << i;
                   }
                   before = after;
                 }
                 EXPECT_GT(fouls, 0) << "a frame with no foul tests half of it";
                 EXPECT_GT(pots, 0);
                 EXPECT_EQ(doc["score"], before);
                 const std::string winner = doc["winner"];
                 ASSERT_TRUE(winner == "A" || winner == "B") << winner;
                 EXPECT_GT(pointsOf(doc["score"], winner), pointsOf(doc["score"], other(winner)));
               });
}

TEST(MatchInvariants, AThreeCushionGameBetweenTwoComputersCountsPointsAndInnings) {
  playAndCheck(R"({"game": "three-cushion", "seed": 3, "points": 4,
                   "players": {"A": "ai:advanced", "B": "ai:pro"}})",
               [](const nlohmann::ordered_json& doc) {
                 nlohmann::ordered_json before = {{"A", {{"points", 0}, {"innings", 0}}},
                                                  {"B", {{"points", 0}, {"innings", 0}}}};
                 std::string last_shooter;
                 int points = 0;
                 for (std::size_t i = 0; i < doc["turns"].size(); ++i) {
                   const auto& t = doc["turns"][i];
                   const std::string shooter = t["shooter"], them = other(shooter);
                   const auto& after = t["score"];
                   const bool point = t["point"];
                   EXPECT_EQ(pointsOf(after, shooter) - pointsOf(before, shooter), point ? 1 : 0)
                       << "turn " << i;
                   EXPECT_EQ(pointsOf(after, them), pointsOf(before, them)) << "turn " << i;
                   // A point takes three cushions at least before the second ball.
                   if (point) {
                     EXPECT_GE(t["cushions"].get<int>(), 3) << "turn " << i;
                   }
                   // An inning starts when a player comes to the table.
                   const int new_inning = shooter != last_shooter ? 1 : 0;
                   EXPECT_EQ(after[shooter]["innings"].get<int>(),
                             before[shooter]["innings"].get<int>() + new_inning)
                       << "turn " << i;
                   // A point keeps the shooter at the table, but the one that reaches the
                   // distance hands the other player the equal inning.
                   const bool reached = pointsOf(after, shooter) == doc["points"].get<int>();
                   if (t["winner"].is_null()) {
                     EXPECT_EQ(t["next"], point && !reached ? shooter : them) << "turn " << i;
                   }
                   for (const std::string p : {"A", "B"}) {
                     const int innings = after[p]["innings"];
                     const double average =
                         innings == 0 ? 0.0 : pointsOf(after, p) / static_cast<double>(innings);
                     EXPECT_DOUBLE_EQ(after[p]["average"].get<double>(), average) << "turn " << i;
                     EXPECT_LE(after[p]["high_run"].get<int>(), pointsOf(after, p)) << "turn " << i;
                   }
                   points += point;
                   last_shooter = shooter;
                   before = after;
                 }
                 EXPECT_GT(points, 0);
                 EXPECT_EQ(doc["score"], before);
                 // The distance reached, and the other player given the equal inning.
                 EXPECT_EQ(doc["draw"], false);
                 const std::string winner = doc["winner"];
                 ASSERT_TRUE(winner == "A" || winner == "B") << winner;
                 EXPECT_EQ(pointsOf(doc["score"], winner), doc["points"].get<int>());
                 EXPECT_EQ(doc["score"]["A"]["innings"], doc["score"]["B"]["innings"]);
               });
}

}  // namespace
}  // namespace nineball::io
