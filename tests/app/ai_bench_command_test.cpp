// nineball ai-bench's JSON contract and the computer-pool tournaments' noise (issue 30's first
// deliveries): the fields, what they count, and bad input refused.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/cli_runner.hpp"

namespace nineball::testing {
namespace {

nlohmann::ordered_json benchJson(const std::string& args) {
  const CliOutcome r = runNineball("ai-bench --json " + args);
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::ordered_json::parse(r.out);
}

TEST(AiBenchJson, OneObjectWithEveryFieldOfTheContract) {
  const nlohmann::ordered_json j =
      benchJson("--game eight-ball --level easy --positions 4 --racks 2");
  ASSERT_TRUE(j.is_object());
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"game", "level", "noise", "positions", "racks", "shots",
                                            "think_s", "shots_simulated_per_cpu_s"}));
  EXPECT_EQ(j["game"], "eight-ball");
  EXPECT_EQ(j["level"], "casual");  // "easy" is its older name
  EXPECT_EQ(j["noise"], "level");
  EXPECT_EQ(j["positions"]["of"], 4);
  EXPECT_LE(j["positions"]["made"].get<int>(), 4);
  EXPECT_GE(j["positions"]["fouls"].get<int>(), 0);
  EXPECT_EQ(j["racks"]["of"], 2);
  EXPECT_LE(j["racks"]["runouts"].get<int>(), 2);
  EXPECT_LE(j["racks"]["ball_down_on_break"].get<int>(), 2);
  // Every rack starts with the computer's break: at least one shot each.
  EXPECT_GE(j["shots"]["attempted"].get<int>(), 2);
  EXPECT_LE(j["shots"]["succeeded"].get<int>(), j["shots"]["attempted"].get<int>());
  EXPECT_LE(j["think_s"]["median"].get<double>(), j["think_s"]["max"].get<double>());
  EXPECT_GT(j["shots_simulated_per_cpu_s"].get<double>(), 0.0);
}

TEST(AiBenchJson, TheTournamentNoiseIsNamedAndChangesTheCueing) {
  const std::string racks = "--game eight-ball --level hard --positions 3 --racks 2";
  const nlohmann::ordered_json level = benchJson(racks);
  const nlohmann::ordered_json olympiad = benchJson(racks + " --noise olympiad");
  const nlohmann::ordered_json five = benchJson(racks + " --noise olympiad-5x");
  EXPECT_EQ(olympiad["noise"], "olympiad");
  EXPECT_EQ(five["noise"], "olympiad-5x");
  // The same seeds and planner, other cueing errors: the racks are played out differently
  // (one rack alone a master under the Olympiad's noise clears as with its own).
  EXPECT_NE(level["shots"], olympiad["shots"]);
  EXPECT_NE(olympiad["shots"], five["shots"]);
  const nlohmann::ordered_json none =
      benchJson("--game nine-ball --level beginner --positions 6 --racks 0 --noise none");
  const nlohmann::ordered_json own =
      benchJson("--game nine-ball --level beginner --positions 6 --racks 0");
  EXPECT_EQ(none["noise"], "none");
  EXPECT_GT(none["positions"]["made"].get<int>(), own["positions"]["made"].get<int>())
      << "a beginner struck as planned pots more";
}

TEST(AiBenchJson, VersusPlaysWholeRacksBetweenTwoLevels) {
  const nlohmann::ordered_json j = benchJson("--versus beginner,hard --racks 4 --positions 0");
  ASSERT_TRUE(j.contains("versus"));
  const auto& v = j["versus"];
  EXPECT_EQ(v["A"], "beginner");
  EXPECT_EQ(v["B"], "master");
  EXPECT_EQ(v["racks"], 4);
  const int a = v["wins"]["A"], b = v["wins"]["B"];
  EXPECT_LE(a + b, 4);
  EXPECT_GT(b, a);                 // the break alternates, and master wins anyway
  EXPECT_EQ(j["racks"]["of"], 0);  // no run-out racks of --level were played
  const CliOutcome bad = runNineball("ai-bench --versus easy --racks 2 --positions 0");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--versus"), std::string::npos) << bad.err;
}

TEST(AiBenchJson, AnUnknownNoiseIsRefused) {
  const CliOutcome r = runNineball("ai-bench --json --noise loud --positions 1 --racks 0");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("--noise"), std::string::npos) << r.err;
}

// Three-cushion reports points per inning: exactly the contract's fields, one inning a position.
TEST(AiBenchJson, ThreeCushionReportsPointsPerInning) {
  const nlohmann::ordered_json j = benchJson("--game three-cushion --level casual --positions 4");
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"game", "level", "points", "innings", "average",
                                            "high_run", "think_s"}));
  EXPECT_EQ(j["game"], "three-cushion");
  EXPECT_EQ(j["level"], "casual");
  EXPECT_EQ(j["innings"], 4);  // no games unless --racks asks for them
  EXPECT_GE(j["points"].get<int>(), j["high_run"].get<int>());
  EXPECT_DOUBLE_EQ(j["average"].get<double>(), j["points"].get<double>() / 4.0);
  EXPECT_LE(j["think_s"]["median"].get<double>(), j["think_s"]["max"].get<double>());
  const CliOutcome versus =
      runNineball("ai-bench --json --game three-cushion --versus club,pro --racks 2");
  EXPECT_EQ(versus.status, 2);
  EXPECT_NE(versus.err.find("--versus"), std::string::npos) << versus.err;
}

}  // namespace
}  // namespace nineball::testing
