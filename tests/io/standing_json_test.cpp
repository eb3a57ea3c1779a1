// A match script that joins a rack in the middle: the shooter, ball in hand, foul counts,
// groups and score given beside the balls.
#include "io/standing_json.hpp"

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "io/match_json.hpp"
#include "io/match_play.hpp"

namespace nineball::io {
namespace {

using nlohmann::ordered_json;

ordered_json eightBallMidRack() {
  return {{"game", "eight-ball"},
          {"balls",
           {{{"id", 0}, {"x", -0.5}, {"y", 0.0}},
            {{"id", 1}, {"x", 0.5}, {"y", 0.1}},
            {{"id", 9}, {"x", 0.6}, {"y", -0.2}},
            {{"id", 8}, {"x", 0.9}, {"y", 0.3}}}},
          {"turns", ordered_json::array()}};
}

std::string refusal(const ordered_json& script) {
  const MatchScriptResult parsed = parseMatchScript(script.dump());
  const auto* e = std::get_if<ParseError>(&parsed);
  return e ? e->message : "accepted";
}

TEST(StandingJson, AScriptJoinsARackWithItsShooterFoulsGroupsAndBallInHand) {
  ordered_json script = eightBallMidRack();
  script["shooter"] = "B";
  script["ball_in_hand"] = true;
  script["fouls"] = {{"B", 1}};
  script["groups"] = {{"A", "stripes"}};
  const MatchScriptResult parsed = parseMatchScript(script.dump());
  ASSERT_TRUE(std::holds_alternative<MatchScript>(parsed)) << refusal(script);
  const Match match(std::get<MatchScript>(parsed).setup);
  EXPECT_EQ(match.rack().shooter(), rules::Player::B);
  EXPECT_TRUE(match.cueInHand());
  EXPECT_FALSE(match.rack().isBreak());
  EXPECT_EQ(match.rack().consecutiveFouls(rules::Player::B), 1);
  EXPECT_EQ(match.rack().groups().a, rules::Group::Stripes);
  EXPECT_EQ(match.rack().groups().b, rules::Group::Solids);
  // B, on solids, may hit the 1 first; a pot of the 9 first would be B's foul.
  EXPECT_EQ(match.rack().legalFirstBalls(), (std::vector<int>{1}));
}

TEST(StandingJson, WithoutTheStandingTheRackStartsWithAToShootAsBefore) {
  const MatchScriptResult parsed = parseMatchScript(eightBallMidRack().dump());
  ASSERT_TRUE(std::holds_alternative<MatchScript>(parsed));
  EXPECT_FALSE(std::get<MatchScript>(parsed).setup.standing);
  const Match match(std::get<MatchScript>(parsed).setup);
  EXPECT_EQ(match.rack().shooter(), rules::Player::A);
  EXPECT_FALSE(match.cueInHand());
}

TEST(StandingJson, AStandingTheGameCannotBeInIsRefusedByName) {
  auto with = [](const char* key, const ordered_json& value) {
    ordered_json script = eightBallMidRack();
    script[key] = value;
    return refusal(script);
  };
  EXPECT_EQ(with("groups", {{"A", "solids"}, {"B", "solids"}}),
            "groups: each player takes the group the other does not (or both null: open)");
  EXPECT_EQ(with("fouls", {{"A", 3}}), "fouls.A: must be >= 0 and <= 2, found 3");
  EXPECT_EQ(with("score", {{"A", 2}}), "score: eight-ball keeps no score");
  EXPECT_EQ(with("shooter", "C"), "shooter: expected \"A\" or \"B\", found \"C\"");
  EXPECT_EQ(with("fouls", {{"C", 1}}).rfind("fouls.C: unknown player", 0), 0u)
      << with("fouls", {{"C", 1}});
  EXPECT_EQ(
      refusal({{"game", "nine-ball"}, {"ball_in_hand", true}, {"turns", ordered_json::array()}}),
      "ball_in_hand: a rack joined in the middle needs its \"balls\"");
  EXPECT_EQ(refusal({{"game", "three-cushion"},
                     {"balls",
                      {{{"id", 0}, {"x", -0.5}, {"y", 0.0}},
                       {{"id", 1}, {"x", 0.5}, {"y", 0.1}},
                       {{"id", 2}, {"x", 0.6}, {"y", -0.2}}}},
                     {"ball_in_hand", true},
                     {"turns", ordered_json::array()}}),
            "ball_in_hand: three-cushion has no ball in hand");
}

TEST(StandingJson, AGameThatKeepsAScoreStartsFromTheGivenScore) {
  const ordered_json script = {{"game", "three-cushion"},
                               {"balls",
                                {{{"id", 0}, {"x", -0.5}, {"y", 0.0}},
                                 {{"id", 1}, {"x", 0.5}, {"y", 0.1}},
                                 {{"id", 2}, {"x", 0.6}, {"y", -0.2}}}},
                               {"shooter", "B"},
                               {"score", {{"A", 7}, {"B", 4}}},
                               {"turns", ordered_json::array()}};
  const MatchScriptResult parsed = parseMatchScript(script.dump());
  ASSERT_TRUE(std::holds_alternative<MatchScript>(parsed)) << refusal(script);
  const Match match(std::get<MatchScript>(parsed).setup);
  EXPECT_EQ(match.rack().score(rules::Player::A), 7);
  EXPECT_EQ(match.rack().score(rules::Player::B), 4);
  EXPECT_EQ(match.rack().cueBall(), 1) << "B strikes the yellow";
}

}  // namespace
}  // namespace nineball::io
