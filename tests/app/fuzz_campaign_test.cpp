// The fuzzing widened to the defect classes a campaign against the released code found (each
// class has its own test beside its fix; these draw many cases of each at random, seeded):
// output onto special files; spinning and masse shots through the reference engine, every ball
// ending on the table or pocketed; saved settings and racks with non-ASCII and extreme fields;
// step.max_time over a whole match; oversized --jsonl lines; ball numbers and decision words
// per game. Whatever comes in, the process ends with 0, 2 or 3, never a crash, and a refusal
// names what is wrong.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"
#include "common/limits.hpp"
#include "nineball/random.hpp"
#include "nineball/table.hpp"
#include "window/game_session.hpp"
#include "window/rack_save.hpp"
#include "window/settings.hpp"

namespace nineball::testing {
namespace {

using nlohmann::json;

#ifdef NINEBALL_SANITIZED
constexpr int kScale = 1;  // the sanitizers are ten times slower
#else
constexpr int kScale = 5;
#endif

std::vector<json> parseLines(const std::string& text) {
  std::vector<json> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(json::parse(line));
  return out;
}

// One ball struck with the cue's most spin at any elevation, or set moving with spin up to the
// input's limit, through the reference engine, many to a --jsonl run.
TEST(FuzzCampaign, SpinningAndMasseShotsEndOnTheTableWithTheReferenceEngine) {
  std::uint64_t rng = 20261124;
  const double r = PhysicsParams{}.ball_radius;
  const TableDef table = TableDef::nineFoot();
  std::string lines;
  const int scenes = 120 * kScale;
  for (int i = 0; i < scenes; ++i) {
    json ball = {{"id", 0}, {"x", uniform(rng, -1.2, 1.2)}, {"y", uniform(rng, -0.58, 0.58)}};
    json s = {{"step", {{"engine", "reference"}}}};
    if (i % 2) {
      const double a = uniform(rng, -kPi, kPi), tip = 0.5 * uniform(rng, 0.9, 0.9999);
      s["shot"] = {{"heading_deg", uniform(rng, -180.0, 180.0)},
                   {"speed", uniform(rng, 0.5, limits::kMaxSpeed)},
                   {"tip", {tip * std::cos(a), tip * std::sin(a)}},
                   {"elevation_deg", uniform(rng, 0.0, 89.0)}};
    } else {
      const double w = limits::kMaxSurfaceSpeed / r;  // each component at up to the limit
      const Vec2 v = fromAngle(uniform(rng, -kPi, kPi)) * uniform(rng, 0.0, limits::kMaxSpeed);
      ball["vx"] = v.x;
      ball["vy"] = v.y;
      ball["w"] = {uniform(rng, -w, w), uniform(rng, -w, w), uniform(rng, -w, w)};
    }
    s["balls"] = {ball};
    lines += s.dump() + "\n";
  }
  TempFile in(lines);
  const CliOutcome run = runNineball("sim --jsonl -", in.path());
  ASSERT_TRUE(run.status == 0 || run.status == 3) << run.err.substr(0, 500);
  const auto results = parseLines(run.out);
  ASSERT_EQ(results.size(), static_cast<std::size_t>(scenes));
  for (std::size_t i = 0; i < results.size(); ++i) {
    ASSERT_FALSE(results[i].contains("error")) << i << ": " << results[i]["error"];
    for (const json& b : results[i]["balls"]) {
      if (!b["pocket"].is_null() || b["off_table"].get<bool>()) continue;
      EXPECT_LE(std::abs(b["x"].get<double>()), table.length / 2.0) << "scene " << i;
      EXPECT_LE(std::abs(b["y"].get<double>()), table.width / 2.0) << "scene " << i;
    }
  }
}

// --svg and bench --csv onto every kind of name: a device, a FIFO, a directory or a symlink to
// one is refused with exit 2 and left as it was; a new name, a regular file and a symlink to
// one or to nothing are written.
TEST(FuzzCampaign, OutputOntoSpecialFilesIsRefusedAndLeavesThemAlone) {
  char tmpl[] = "/tmp/nineball-fuzz-out-XXXXXX";
  const std::string dir = mkdtemp(tmpl);
  TempFile scene(R"({"balls": [{"id": 0, "x": 0, "y": 0}], "shot": {"heading_deg": 30,
                     "speed": 2}})");
  std::uint64_t rng = 7;
  for (int i = 0; i < 12 * kScale; ++i) {
    const std::string name = dir + "/out" + std::to_string(i) + ".svg";
    const int kind = static_cast<int>(splitmix64(rng) % 7);
    bool refused = true;
    switch (kind) {
      case 0:
        ASSERT_EQ(mkfifo(name.c_str(), 0600), 0);
        break;
      case 1:
        ASSERT_EQ(mkdir(name.c_str(), 0700), 0);
        break;
      case 2:
        ASSERT_EQ(symlink("/dev/null", name.c_str()), 0);
        break;
      case 3:
        ASSERT_EQ(mkfifo((name + ".p").c_str(), 0600), 0);
        ASSERT_EQ(symlink((name + ".p").c_str(), name.c_str()), 0);
        break;
      case 4:
        std::ofstream(name) << "old";
        refused = false;
        break;
      case 5:
        ASSERT_EQ(symlink((name + ".nowhere").c_str(), name.c_str()), 0);
        refused = false;
        break;
      default:
        refused = false;
        break;
    }
    struct stat before {};
    lstat(name.c_str(), &before);
    const CliOutcome run =
        runNineball("sim " + shellQuoted(scene.path()) + " --svg " + shellQuoted(name));
    struct stat after {};
    ASSERT_EQ(lstat(name.c_str(), &after), 0) << name;
    if (refused) {
      EXPECT_EQ(run.status, 2) << "kind " << kind << ": " << run.err;
      EXPECT_TRUE(run.out.empty());
      EXPECT_NE(run.err.find(name), std::string::npos) << run.err;
      EXPECT_EQ(after.st_mode, before.st_mode) << "kind " << kind << " was replaced";
    } else {
      EXPECT_EQ(run.status, 0) << "kind " << kind << ": " << run.err;
      EXPECT_TRUE(S_ISREG(after.st_mode)) << "kind " << kind;
    }
  }
  struct stat null {};
  ASSERT_EQ(stat("/dev/null", &null), 0);
  EXPECT_TRUE(S_ISCHR(null.st_mode));
  std::filesystem::remove_all(dir);
}

// Lines of random length about the 4 MiB bound, valid and not, in one --jsonl run: each line
// gets one output line, in order; an oversized one is refused by its number.
TEST(FuzzCampaign, OversizedJsonlLinesAreRefusedByNumberAndTheRestRun) {
  std::uint64_t rng = 41;
  const std::string good =
      R"({"balls": [{"id": 0, "x": 0.1, "y": 0}], "shot": {"heading_deg": 10, "speed": 1}})";
  std::string text;
  std::vector<bool> too_long;
  for (int i = 0; i < 4 + 2 * kScale; ++i) {
    const auto pick = splitmix64(rng) % 3;
    if (pick == 0) {
      text += good + "\n";
      too_long.push_back(false);
    } else {
      // Spaces pad a valid scene to about the bound: a space more or less decides.
      const long size = static_cast<long>(limits::kMaxInputBytes) +
                        static_cast<long>(uniform(rng, -64.0, 64.0)) -
                        static_cast<long>(good.size());
      text += std::string(static_cast<std::size_t>(std::max(0L, size)), ' ') + good + "\n";
      too_long.push_back(std::max(0L, size) + static_cast<long>(good.size()) >
                         static_cast<long>(limits::kMaxInputBytes));
    }
  }
  TempFile in(text);
  const CliOutcome run = runNineball("sim --jsonl -", in.path());
  const auto results = parseLines(run.out);
  ASSERT_EQ(results.size(), too_long.size());
  for (std::size_t i = 0; i < results.size(); ++i) {
    EXPECT_EQ(results[i].contains("error"), too_long[i]) << "line " << i + 1;
    if (too_long[i]) {
      EXPECT_EQ(results[i]["line"], static_cast<long>(i) + 1);
    }
  }
}

// Random layouts for each game with ball numbers inside and outside its range, and decision
// words of each game: `match` refuses exactly those the game does not have, naming the field.
TEST(FuzzCampaign, BallNumbersAndDecisionWordsAreTheGamesOwn) {
  std::uint64_t rng = 99;
  const char* games[] = {"nine-ball", "eight-ball", "ten-ball"};
  const char* words[] = {"shoot", "pass", "play-on", "rerack"};
  for (int i = 0; i < 16 * kScale; ++i) {
    const int g = static_cast<int>(splitmix64(rng) % 3);
    const std::string game = games[g];
    json balls = {{{"id", 0}, {"x", -0.9}, {"y", 0.0}}};
    bool bad_ball = false, has_eight = false;
    const int count = 1 + static_cast<int>(splitmix64(rng) % 3);
    for (int k = 0; k < count; ++k) {
      const int id = 1 + static_cast<int>(splitmix64(rng) % 18);
      bool dup = false;
      for (const json& b : balls) dup |= b["id"] == id;
      if (dup) continue;
      balls.push_back({{"id", id}, {"x", -0.3 + 0.2 * k}, {"y", 0.3}});
      has_eight |= id == 8;
      bad_ball |= (g == 1 && id > 15) || (g == 2 && id > 10);
    }
    bad_ball |= g == 1 && !has_eight;
    const bool use_balls = splitmix64(rng) % 2;
    const std::string word = words[splitmix64(rng) % 4];
    const bool eight = g == 1;
    const bool bad_word = eight != (word == "play-on" || word == "rerack");
    json script = {{"game", game},
                   {"turns", {{{"heading_deg", 0}, {"speed", 10}}, {{"decision", word}}}}};
    if (use_balls) script["balls"] = balls;
    const CliOutcome run = runOnDocument("match", script.dump());
    const std::string where = script.dump();
    if (use_balls && bad_ball) {
      EXPECT_EQ(run.status, 2) << where;
      EXPECT_NE(run.err.find(": balls: "), std::string::npos) << run.err << where;
    } else if (bad_word) {
      EXPECT_EQ(run.status, 2) << where;
      EXPECT_NE(run.err.find("turns[1].decision"), std::string::npos) << run.err << where;
    } else {
      // The decision may not be due (the break was legal): refused as an illegal turn, or played.
      EXPECT_TRUE(run.status == 0 || run.status == 2) << run.err << where;
      EXPECT_EQ(run.err.find("decision: expected"), std::string::npos) << run.err << where;
    }
  }
}

// step.max_time is each shot's: a match of slow shots under a limit each fits runs every turn
// to rest, however long the match.
TEST(FuzzCampaign, MaxTimeHoldsPerShotOverAWholeMatch) {
  std::uint64_t rng = 5;
  for (int i = 0; i < 2 * kScale; ++i) {
    json turns = json::array();
    // Five fouls (no ball hit): the third of one player's ends the rack, 20 s of shots in all.
    for (int k = 0; k < 5; ++k) {
      turns.push_back({{"heading_deg", k % 2 ? -90.0 : 90.0}, {"speed", uniform(rng, 0.8, 1.2)}});
    }
    const json script = {{"balls",
                          {{{"id", 0}, {"x", -0.6}, {"y", 0.0}},
                           {{"id", 1}, {"x", 0.9}, {"y", 0.45}},
                           {{"id", 9}, {"x", 0.9}, {"y", -0.45}}}},
                         {"step", {{"max_time", 10}}},
                         {"turns", turns}};
    const CliOutcome run = runOnDocument("match", script.dump());
    ASSERT_EQ(run.status, 0) << run.err;
    const json result = json::parse(run.out);
    EXPECT_FALSE(result["partial"].get<bool>());
    EXPECT_EQ(result["turns"].size(), 5u);
  }
}

}  // namespace
}  // namespace nineball::testing

namespace nineball::app {
namespace {

using nlohmann::json;

std::string randomText(std::uint64_t& rng) {
  const auto kind = splitmix64(rng) % 4;
  std::string s;
  const int n = static_cast<int>(splitmix64(rng) % 80);
  for (int i = 0; i < n; ++i) {
    switch (kind) {
      case 0:  // ASCII
        s += static_cast<char>(' ' + splitmix64(rng) % 95);
        break;
      case 1:  // valid UTF-8 of every length
        s += std::vector<std::string>{"a", "\xc3\xa9", "\xe2\x82\xac",
                                      "\xf0\x9f\x8e\xb1"}[splitmix64(rng) % 4];
        break;
      default:  // any bytes
        s += static_cast<char>(splitmix64(rng) % 256);
        break;
    }
  }
  return s;
}

json extreme(std::uint64_t& rng) {
  switch (splitmix64(rng) % 8) {
    case 0:
      return 2147483647;
    case 1:
      return -1;
    case 2:
      return 1e308;
    case 3:
      return 3.14159265358979;
    case 4:
      return "x";
    case 5:
      return nullptr;
    default:
      return static_cast<int>(splitmix64(rng) % 5);
  }
}

class SavedFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("nineball-fuzz-saved-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir_);
    setenv("XDG_STATE_HOME", dir_.c_str(), 1);
    setenv("XDG_CONFIG_HOME", dir_.c_str(), 1);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

// Saved settings and racks with names of any bytes and fields at their extremes: loading never
// throws; what is loaded can be written back and, for a rack, replayed or refused as the game
// does (no exception escapes but the IllegalAction the game catches).
TEST_F(SavedFiles, AnySavedFieldLoadsSavesAndResumesWithoutEndingTheProgram) {
  std::uint64_t rng = 77;
  for (int i = 0; i < 300 * testing::kScale; ++i) {
    const json settings = {{"volume", extreme(rng)},
                           {"last",
                            {{"names", {randomText(rng), randomText(rng)}},
                             {"game", i % 2 ? json("ten-ball") : extreme(rng)},
                             {"rules", i % 3 ? json("paper") : extreme(rng)}}}};
    std::ofstream(window::settingsPath())
        << settings.dump(-1, ' ', false, json::error_handler_t::ignore);
    window::Settings s;
    ASSERT_NO_THROW(s = window::loadSettings(window::settingsPath())) << i;
    std::string why;
    ASSERT_NO_THROW(window::saveSettings(s, window::settingsPath(), why)) << i;

    json turn = {{"kind", i % 5 ? "shot" : "decision"},
                 {"heading_rad", extreme(rng)},
                 {"speed", i % 4 ? json(uniform(rng, 0.0, 20.0)) : extreme(rng)},
                 {"tip", {uniform(rng, -1, 1), uniform(rng, -1, 1)}},
                 {"elevation_rad", uniform(rng, -1, 4)},
                 {"shoot", true}};
    const json rack = {{"version", 1},
                       {"game", std::vector<std::string>{"nine-ball", "eight-ball",
                                                         "ten-ball"}[splitmix64(rng) % 3]},
                       {"rules", i % 2 ? "wpa" : "paper"},
                       {"seed", splitmix64(rng)},
                       {"rack", extreme(rng)},
                       {"racks_won", {extreme(rng), extreme(rng)}},
                       {"names", {randomText(rng), randomText(rng)}},
                       {"opponent", "human"},
                       {"turns", {turn}}};
    const std::string path = window::rackSavePath();
    std::ofstream(path) << rack.dump(-1, ' ', false, json::error_handler_t::ignore);
    std::optional<window::SavedRack> loaded;
    ASSERT_NO_THROW(loaded = window::loadRack(path)) << i;
    if (!loaded) {
      EXPECT_FALSE(std::filesystem::exists(path)) << "a refused rack is deleted";
      continue;
    }
    ASSERT_NO_THROW(window::rackToJson(*loaded).dump()) << i;
    MatchSetup setup;
    setup.game = loaded->game;
    setup.rules = loaded->rules;
    setup.seed = loaded->seed;
    try {
      window::GameSession session(setup);
      window::replayRack(session, *loaded);
    } catch (const IllegalAction&) {
      // Refused as the game refuses it: the rack is dropped with a warning.
    }
  }
}

}  // namespace
}  // namespace nineball::app
