// The `nineball fit` and `nineball calibrate` contracts, run through the real binary.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "app/cli_runner.hpp"
#include "fit/carom_shot.hpp"
#include "io/recording_json.hpp"
#include "io/scene_json.hpp"

using nineball::testing::CliOutcome;
using nineball::testing::runNineball;
using nineball::testing::shellQuoted;
using nineball::testing::TempFile;

namespace nineball {
namespace {

Recording recorded(double heading_deg, double speed, std::uint64_t seed) {
  const Scene s = testing::caromShot(heading_deg, speed);
  Tracker t;
  t.seed = seed;
  return recordScene(s, {"white", "yellow", "red"}, t, "shot-" + std::to_string(seed));
}

std::string jsonLines(const std::vector<Recording>& shots) {
  std::string text;
  for (const Recording& r : shots) text += io::recordingToJson(r).dump() + "\n";
  return text;
}

// The members in the order printed.
std::vector<std::string> keys(const nlohmann::ordered_json& j) {
  std::vector<std::string> k;
  for (const auto& item : j.items()) k.push_back(item.key());
  return k;
}

TEST(FitCli, PrintsOneLineAShotWhoseSceneReproducesTheFit) {
  const std::vector<Recording> shots{recorded(19.0, 3.0, 1), recorded(25.0, 2.0, 2)};
  TempFile file(jsonLines(shots));
  const CliOutcome r = runNineball("fit " + shellQuoted(file.path()));
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line;
  std::size_t n = 0;
  while (std::getline(lines, line)) {
    const auto j = nlohmann::ordered_json::parse(line);
    EXPECT_EQ(keys(j),
              (std::vector<std::string>{"id", "scene", "names", "strike_time", "rmse_m", "evals"}));
    EXPECT_EQ(j["id"], shots[n].id);
    // The cue ball (the first to move) is 0; the others follow as the recording lists them.
    EXPECT_EQ(j["names"]["0"], "white");
    std::vector<std::string> names;
    for (const auto& item : j["names"].items()) names.push_back(item.value());
    EXPECT_EQ(names.size(), 3u);
    EXPECT_EQ(keys(j["rmse_m"]), (std::vector<std::string>{"full", "early"}));
    EXPECT_LE(j["evals"].get<int>(), 12000 + 20);  // the default budget
    // The printed scene, read as `nineball sim` reads it, gives the printed error again.
    auto scene = io::parseScene(j["scene"].dump());
    ASSERT_TRUE(std::holds_alternative<Scene>(scene)) << std::get<io::ParseError>(scene).message;
    const FitErrors e =
        fitErrors(shots[n], std::get<Scene>(scene), names, j["strike_time"].get<double>());
    EXPECT_NEAR(e.full, j["rmse_m"]["full"].get<double>(), 1e-9);
    EXPECT_NEAR(e.early, j["rmse_m"]["early"].get<double>(), 1e-9);
    // A tracker's 5 mm on each coordinate is 7.1 mm at best; a fit found is near it.
    EXPECT_LT(e.full, 0.012);
    ++n;
  }
  EXPECT_EQ(n, shots.size());
}

TEST(FitCli, TheSameSeedGivesTheSameFitsOnOneOrTwoThreads) {
  TempFile file(
      jsonLines({recorded(19.0, 3.0, 1), recorded(25.0, 2.0, 2), recorded(12.0, 2.5, 3)}));
  const std::string fit = "fit " + shellQuoted(file.path()) + " --evals 400 --seed 9";
  const CliOutcome one = runNineball(fit + " --threads 1");
  const CliOutcome two = runNineball(fit + " --threads 2");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(one.out, two.out);
}

TEST(FitCli, RefusesBadRecordingsByName) {
  nlohmann::json good = io::recordingToJson(recorded(19.0, 3.0, 1));
  auto refused = [](const nlohmann::json& doc, const std::string& args = "") {
    TempFile file(doc.dump());
    return runNineball("fit " + shellQuoted(file.path()) + " --evals 60" + args);
  };
  nlohmann::json backwards = good;
  backwards["balls"]["red"]["t"][5] = 0.0;
  CliOutcome r = refused(backwards);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("balls.red.t: not increasing at sample 5"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());

  nlohmann::json unknown = good;
  unknown["speed"] = 3;
  r = refused(unknown);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("speed"), std::string::npos) << r.err;

  nlohmann::json cue = good;
  cue["cue_ball"] = "blue";
  r = refused(cue);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cue_ball: no ball named \"blue\""), std::string::npos) << r.err;

  nlohmann::json lengths = good;
  lengths["balls"]["white"]["x"].erase(0);
  r = refused(lengths);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("balls.white"), std::string::npos) << r.err;

  r = refused(nlohmann::json::array({good, nlohmann::json{{"balls", 3}}}));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("shot 2: balls"), std::string::npos) << r.err;

  r = refused(good, " --objective middle");
  EXPECT_EQ(r.status, 2);
}

TEST(FitCli, ReadsOneShotPrettyPrintedAnArrayOfThemAndJsonLines) {
  const nlohmann::json a = io::recordingToJson(recorded(19.0, 3.0, 1));
  const nlohmann::json b = io::recordingToJson(recorded(25.0, 2.0, 2));
  auto lines = [](const std::string& document) {
    TempFile file(document);
    const CliOutcome r = runNineball("fit " + shellQuoted(file.path()) + " --evals 60");
    EXPECT_EQ(r.status, 0) << r.err;
    std::size_t n = 0;
    for (char c : r.out) n += c == '\n';
    return n;
  };
  EXPECT_EQ(lines(a.dump(2)), 1u);
  EXPECT_EQ(lines(nlohmann::json::array({a, b}).dump(2)), 2u);
  EXPECT_EQ(lines(a.dump() + "\n\n" + b.dump() + "\n"), 2u);
  // A bad line of JSON Lines is named by its number.
  TempFile file(a.dump() + "\n{\"balls\": }\n");
  const CliOutcome r = runNineball("fit " + shellQuoted(file.path()) + " --evals 60");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("line 2:"), std::string::npos) << r.err;
}

TEST(CalibrateCli, PrintsThePhysicsAndTheMediansOfBothSets) {
  const std::vector<Recording> shots{recorded(19.0, 3.0, 1), recorded(25.0, 2.0, 2),
                                     recorded(12.0, 2.5, 3)};
  TempFile file(jsonLines(shots));
  const CliOutcome r =
      runNineball("calibrate " + shellQuoted(file.path()) +
                  " --params rolling_friction,cushion_restitution --holdout 0.34 --evals 400 "
                  "--refit-evals 30 --candidates 6");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(keys(j),
            (std::vector<std::string>{"physics", "parameters", "uncertainty", "correlation",
                                      "converged", "convergence", "train", "holdout", "per_shot"}));
  // Each parameter in --params order, its value the calibrated physics', with its standard
  // error (a number, or null where the search cannot determine it).
  EXPECT_EQ(keys(j["parameters"]),
            (std::vector<std::string>{"rolling_friction", "cushion_restitution"}));
  for (const auto& [name, p] : j["parameters"].items()) {
    EXPECT_EQ(keys(p), (std::vector<std::string>{"value", "stderr"}));
    EXPECT_EQ(p["value"], j["physics"][name]);
    EXPECT_TRUE(p["stderr"].is_number() || p["stderr"].is_null());
  }
  EXPECT_EQ(j["uncertainty"],
            nlohmann::ordered_json({{"method", "bootstrap over shots"}, {"resamples", 200}}));
  ASSERT_EQ(j["correlation"].size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    ASSERT_EQ(j["correlation"][k].size(), 2u);
    EXPECT_EQ(j["correlation"][k][k], 1.0);
  }
  EXPECT_EQ(j["correlation"][0][1], j["correlation"][1][0]);
  EXPECT_TRUE(j["converged"].is_boolean());
  EXPECT_FALSE(j["convergence"].get<std::string>().empty());
  // The last line of progress: the calibrated values with their standard errors.
  EXPECT_EQ(r.err.back(), '\n');
  EXPECT_NE(r.err.substr(r.err.rfind('\n', r.err.size() - 2))
                .find("calibrate: calibrated (standard errors: bootstrap over shots, 200 "
                      "resamples): rolling_friction "),
            std::string::npos)
      << r.err;
  EXPECT_EQ(j["train"]["shots"], 2);
  EXPECT_EQ(j["holdout"]["shots"], 1);
  EXPECT_TRUE(j["holdout"]["median_rmse_m"].is_number());
  EXPECT_EQ(j["per_shot"].size(), 3u);
  // The calibrated block reads back as a scene's physics.
  nlohmann::ordered_json scene{{"table", "carom"},
                               {"physics", j["physics"]},
                               {"balls", {{{"id", 0}, {"x", 0.0}, {"y", 0.0}}}}};
  EXPECT_TRUE(std::holds_alternative<Scene>(io::parseScene(scene.dump())));
}

TEST(CalibrateCli, RefusesParametersThePhysicsDoesNotTake) {
  TempFile file(io::recordingToJson(recorded(19.0, 3.0, 1)).dump());
  CliOutcome r = runNineball("calibrate " + shellQuoted(file.path()) + " --params nonsense");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("\"nonsense\""), std::string::npos) << r.err;
  r = runNineball("calibrate " + shellQuoted(file.path()) +
                  " --params rolling_friction,rolling_friction");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("named twice"), std::string::npos) << r.err;
  // The damping cloth reads no rolling resistance: refused, naming what it reads.
  nlohmann::json damped = io::recordingToJson(recorded(19.0, 3.0, 1));
  damped["physics"] = {{"preset", "carom"}, {"cloth", "damping"}};
  TempFile other(damped.dump());
  r = runNineball("calibrate " + shellQuoted(other.path()) + " --params rolling_friction");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("linear_damping"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace nineball
