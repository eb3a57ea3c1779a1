// The `nineball fit` and `nineball calibrate` contracts, run through the real binary.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "app/cli_runner.hpp"
#include "app/fit_command.hpp"
#include "common/limits.hpp"
#include "fit/carom_shot.hpp"
#include "io/recording_json.hpp"
#include "io/scene_json.hpp"

using nineball::testing::CliOutcome;
using nineball::testing::runNineball;
using nineball::testing::runOnDocument;
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
    EXPECT_EQ(keys(j), (std::vector<std::string>{"id", "scene", "names", "strike_time", "rmse_m",
                                                 "evals", "warnings", "unreproduced"}));
    EXPECT_TRUE(j["warnings"].is_array());
    EXPECT_EQ(j["unreproduced"], nlohmann::ordered_json::array());
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
  EXPECT_NE(r.err.find("balls.red.t: decreasing at sample 5"), std::string::npos) << r.err;
  // The refused shot's line in its place.
  EXPECT_EQ(r.out, "{\"id\":\"shot-1\",\"error\":\"balls.red.t: decreasing at sample 5\"}\n");

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
  EXPECT_NE(r.err.find("1 of 2 shots refused"), std::string::npos) << r.err;

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
  // A bad line of JSON Lines is named by its number, and has its line.
  TempFile file(a.dump() + "\n{\"balls\": }\n");
  const CliOutcome r = runNineball("fit " + shellQuoted(file.path()) + " --evals 60");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("line 2:"), std::string::npos) << r.err;
  std::istringstream out(r.out);
  std::string first, second;
  std::getline(out, first);
  std::getline(out, second);
  EXPECT_TRUE(nlohmann::json::parse(first).contains("scene")) << first;
  EXPECT_EQ(keys(nlohmann::ordered_json::parse(second)), std::vector<std::string>{"error"});
}

std::vector<nlohmann::json> linesOf(const std::string& out) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

// Two samples 1e-200 s apart imply 6e+196 m/s: once a crash (SIGSEGV), now a refusal by name.
const char* const kImpossible =
    R"({"id": "impossible", "balls": {"white": {"t": [0, 1e-200], "x": [-0.6, -0.5994],)"
    R"( "y": [0, 0]}}})";

TEST(FitCli, ARefusedShotHasItsLineInItsPlaceAndTheOthersAreFitted) {
  const Recording a = recorded(19.0, 3.0, 1);
  const Recording b = recorded(25.0, 2.0, 2);
  TempFile file(io::recordingToJson(a).dump() + "\n" + kImpossible + "\n" +
                io::recordingToJson(b).dump() + "\n");
  const CliOutcome r = runNineball("fit " + shellQuoted(file.path()) + " --evals 200");
  EXPECT_EQ(r.status, 2) << r.err;
  const std::vector<nlohmann::json> lines = linesOf(r.out);
  ASSERT_EQ(lines.size(), 3u) << r.out;
  EXPECT_EQ(lines[0]["id"], "shot-1");
  EXPECT_TRUE(lines[0]["rmse_m"]["full"].is_number());
  EXPECT_EQ(lines[1], (nlohmann::json{{"id", "impossible"},
                                      {"error", "balls.white: samples 0-1 imply 6e+196 m/s"}}));
  EXPECT_EQ(lines[2]["id"], "shot-2");
  EXPECT_TRUE(lines[2]["rmse_m"]["full"].is_number());
  EXPECT_NE(r.err.find("line 2: balls.white: samples 0-1 imply 6e+196 m/s"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("1 of 3 shots refused"), std::string::npos) << r.err;
}

TEST(FitCli, ARefusedShotWithoutAnIdHasAnErrorAlone) {
  CliOutcome r = runOnDocument("fit", R"({"balls": {"white": {"t": [0, 1e-200],)"
                                      R"( "x": [-0.6, -0.5994], "y": [0, 0]}}})");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "{\"error\":\"balls.white: samples 0-1 imply 6e+196 m/s\"}\n");
  EXPECT_NE(r.err.find(": balls.white: samples 0-1 imply 6e+196 m/s"), std::string::npos) << r.err;
  // What is no JSON at all is refused whole.
  r = runOnDocument("fit", "[{\"balls\": ");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(FitCli, FitsRepeatedTimes) {
  Recording shot = recorded(19.0, 3.0, 1);
  for (RecordedPath& b : shot.balls) {
    for (std::size_t i = 3; i < b.t.size(); i += 3) b.t[i] = b.t[i - 1];
  }
  const CliOutcome r = runOnDocument("fit --evals 200", io::recordingToJson(shot).dump());
  EXPECT_EQ(r.status, 0) << r.err;
  const std::vector<nlohmann::json> lines = linesOf(r.out);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(lines[0]["rmse_m"]["full"].is_number()) << r.out;
}

TEST(FitCli, PrintsAnIdAsItCame) {
  nlohmann::json a = io::recordingToJson(recorded(19.0, 3.0, 1));
  nlohmann::json b = a;
  a["id"] = 123;
  b["id"] = "123";
  const CliOutcome r = runOnDocument(
      "fit --evals 60", nlohmann::json::array({a, b, nlohmann::json::parse(kImpossible)}).dump());
  const std::vector<nlohmann::json> lines = linesOf(r.out);
  ASSERT_EQ(lines.size(), 3u) << r.out << r.err;
  EXPECT_EQ(lines[0]["id"], 123);
  EXPECT_EQ(lines[1]["id"], "123");
}

// Standard output that raises SIGINT once its first line is out, as if Ctrl-C were pressed
// then.
class CtrlCAfterTheFirstLine : public std::stringbuf {
 protected:
  int sync() override {
    if (!pressed_ && str().find('\n') != std::string::npos) {
      pressed_ = true;
      std::raise(SIGINT);
    }
    return std::stringbuf::sync();
  }

 private:
  bool pressed_ = false;
};

TEST(FitCli, PrintsEachLineOnceDoneAndStopsAtCtrlC) {
  TempFile file(jsonLines({recorded(19.0, 3.0, 1), recorded(25.0, 2.0, 2)}));
  app::FitCommandOptions options;
  options.path = file.path();
  options.evals = 200;
  options.threads = 1;
  CtrlCAfterTheFirstLine printed;
  std::ostream out(&printed);
  std::istringstream in;
  std::ostringstream err;
  // Ctrl-C as a terminal delivers it: a test run started in the background inherits it ignored.
  void (*const before)(int) = std::signal(SIGINT, SIG_DFL);
  // The first shot's line is out while the second is still to fit: Ctrl-C then stops it.
  EXPECT_EQ(app::runFit(options, in, out, err), 130);
  const std::vector<nlohmann::json> lines = linesOf(printed.str());
  ASSERT_EQ(lines.size(), 1u) << printed.str();
  EXPECT_EQ(lines[0]["id"], "shot-1");
  EXPECT_NE(err.str().find("interrupted: 1 of 2 shots printed"), std::string::npos) << err.str();
  // Ctrl-C does again what it did before the run.
  EXPECT_EQ(std::signal(SIGINT, before), SIG_DFL);
}

TEST(FitCli, StopsAtSigtermAndExits130) {
  TempFile file(jsonLines({recorded(19.0, 3.0, 1), recorded(25.0, 2.0, 2)}));
  const auto start = std::chrono::steady_clock::now();
  // --foreground: timeout then signals the fit alone. Without it, it also signals its process
  // group, the fit again: a second TERM ends the fit at once by design (exit 143), whenever the
  // first one's handler has run before the second arrives.
  const CliOutcome r =
      runNineball("fit " + shellQuoted(file.path()) + " --evals 1000000 --threads 1", "/dev/null",
                  "timeout --foreground --preserve-status -s TERM 1 ");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.status, 130) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("interrupted: 0 of 2 shots printed"), std::string::npos) << r.err;
  EXPECT_LT(seconds, 10.0);
}

// A ball at rest sampled every millisecond for 1000 s, the most samples a ball may have:
// 12 MB of JSON, over 100 MB parsed.
std::string longestRecording() {
  std::string t, x;
  for (std::size_t i = 0; i < limits::kMaxRecordedSamples; ++i) {
    t += (i ? "," : "") + std::to_string(i) + "e-3";
    x += i ? ",0" : "0";
  }
  return R"({"balls": {"white": {"t": [)" + t + "], \"x\": [" + x + "], \"y\": [" + x + "]}}}";
}

TEST(FitCli, SaysWhenMemoryRunsOutInsteadOfAborting) {
#ifdef NINEBALL_SANITIZED
  GTEST_SKIP() << "the sanitizers' shadow memory does not fit under an address-space limit";
#endif
  TempFile file(longestRecording());
  // Address-space limits (KiB) above what nineball needs to start, below what the file needs.
  for (int limit : {30000, 60000}) {
    for (const std::string command : {"fit", "calibrate"}) {
      const std::string params = command == "calibrate" ? " --params rolling_friction" : "";
      const CliOutcome r =
          runNineball(command + " " + shellQuoted(file.path()) + params + " --threads 2",
                      "/dev/null", "ulimit -v " + std::to_string(limit) + "; ");
      EXPECT_EQ(r.status, 1) << limit << " KiB: " << r.err;
      EXPECT_EQ(r.err, "nineball " + command + ": out of memory\n") << limit << " KiB";
    }
  }
}

TEST(CalibrateCli, RefusesTheRunNamingARefusedShot) {
  const nlohmann::json good = io::recordingToJson(recorded(19.0, 3.0, 1));
  const CliOutcome r =
      runOnDocument("calibrate --params rolling_friction",
                    nlohmann::json::array({good, good, nlohmann::json::parse(kImpossible)}).dump());
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("shot 3: balls.white: samples 0-1 imply 6e+196 m/s"), std::string::npos)
      << r.err;
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
  EXPECT_EQ(keys(j["train"]),
            (std::vector<std::string>{"median_rmse_m", "shots", "unreproduced_balls"}));
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
  EXPECT_TRUE(j["holdout"]["unreproduced_balls"].is_number_integer());
  EXPECT_TRUE(j["per_shot"][0]["warnings"].is_array());
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
