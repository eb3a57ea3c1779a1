// A rack saved on quit and resumed: the turns replayed give the same balls, bit for bit.
#include "window/rack_save.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/computer_race.hpp"
#include "window/game_rolling.hpp"
#include "window/game_session.hpp"

namespace nineball::window {
namespace {

class RackFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("nineball-rack-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    const char* v = std::getenv("XDG_STATE_HOME");
    if (v) saved_ = v;
    setenv("XDG_STATE_HOME", dir_.c_str(), 1);
  }
  void TearDown() override {
    if (saved_) {
      setenv("XDG_STATE_HOME", saved_->c_str(), 1);
    } else {
      unsetenv("XDG_STATE_HOME");
    }
    std::filesystem::remove_all(dir_);
  }
  std::filesystem::path dir_;
  std::optional<std::string> saved_;
};

TEST_F(RackFiles, SaveLoadReplayGivesTheSameBalls) {
  MatchSetup setup;
  setup.seed = 7;
  GameSession played(setup);
  played.setSeatName(0, "Ann");
  // The break, then a few shots with spin, tilt and the cue ball placed when in hand.
  ASSERT_TRUE(played.shoot());
  ASSERT_TRUE(roll(played));
  const double headings[] = {0.3, -1.1, 2.0, 0.7};
  for (double h : headings) {
    if (played.phase() != Phase::Aiming) break;
    played.setHeading(h);
    played.setSpeed(2.345678901);
    played.setTip({0.1234567, -0.2});
    played.setElevation(0.05);
    ASSERT_TRUE(played.shoot());
    ASSERT_TRUE(roll(played));
  }
  ASSERT_GE(played.rackTurns().size(), 2u);

  const std::string path = rackSavePath();
  EXPECT_EQ(path, (dir_ / "nineball" / "rack.json").string());
  std::string why;
  ASSERT_TRUE(saveRack(saveOf(played, ComputerSeat{ai::Level::Club}), path, why)) << why;
  const auto loaded = loadRack(path);
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->turns.size(), played.rackTurns().size());
  EXPECT_EQ(loaded->names[0], "Ann");
  EXPECT_EQ(loaded->opponent, Seat(ComputerSeat{ai::Level::Club}));

  MatchSetup again;
  again.rules = loaded->rules;
  again.seed = loaded->seed;
  GameSession resumed(again);
  replayRack(resumed, *loaded);
  const auto a = played.match().balls();
  const auto b = resumed.match().balls();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].id, b[i].id);
    EXPECT_EQ(a[i].pos.x, b[i].pos.x) << "ball " << a[i].id;
    EXPECT_EQ(a[i].pos.y, b[i].pos.y) << "ball " << a[i].id;
    EXPECT_EQ(a[i].pocket.has_value(), b[i].pocket.has_value()) << "ball " << a[i].id;
  }
  EXPECT_EQ(resumed.seatToMove(), played.seatToMove());
  EXPECT_EQ(resumed.phase(), played.phase());
  EXPECT_EQ(resumed.seatName(0), "Ann");
  forgetRack(path);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(loadRack(path));
}

TEST_F(RackFiles, ALaterRackResumesWithItsSeedBreakerAndScore) {
  GameSession played(MatchSetup{});
  played.setBestOf(7);         // a match of frames keeps its length through the save
  played.resumeRack(3, 2, 1);  // as after three racks
  EXPECT_EQ(played.rackNumber(), 4);
  EXPECT_EQ(played.seatToMove(), 1);  // the seats take turns to break
  ASSERT_TRUE(played.shoot());
  ASSERT_TRUE(roll(played));
  const SavedRack saved = saveOf(played, HumanSeat{});
  std::string why;
  const auto back = rackFromJson(nlohmann::json::parse(rackToJson(saved).dump()), why);
  ASSERT_TRUE(back) << why;
  GameSession resumed(MatchSetup{});
  replayRack(resumed, *back);
  EXPECT_EQ(resumed.rackNumber(), 4);
  EXPECT_EQ(resumed.racksWon(0), 2);
  EXPECT_EQ(resumed.racksWon(1), 1);
  EXPECT_EQ(resumed.bestOf(), 7);
  const auto a = played.match().balls();
  const auto b = resumed.match().balls();
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].pos, b[i].pos);
}

TEST_F(RackFiles, AMatchInProgressResumesByPlayingItsRacksAgain) {
  // Ten-ball, race to 2, winner breaks (seed 1: A wins the first rack and breaks the second too):
  // saved three turns before the end, in the second rack or later.
  const test::ComputerRace race = test::computerRace("ten-ball", 2, "winner", 1);
  MatchSetup setup;
  setup.setGame(rules::Game::TenBall);
  setup.seed = 1;
  GameSession played(setup);
  played.setBestOf(3);
  played.setBreaks(BreakOrder::Winner);
  for (std::size_t i = 0; i + 3 < race.turns.size(); ++i) played.playTurn(race.turns[i]);
  ASSERT_GE(played.rackNumber(), 2);
  ASSERT_NE(played.phase(), Phase::GameOver);
  const SavedRack saved = saveOf(played, HumanSeat{});
  EXPECT_EQ(saved.first_rack, 0);
  EXPECT_EQ(saved.match_turns.size(), race.turns.size() - 3);
  std::string why;
  const auto back = rackFromJson(nlohmann::json::parse(rackToJson(saved).dump()), why);
  ASSERT_TRUE(back) << why;
  GameSession resumed(setup);
  replayRack(resumed, *back);
  EXPECT_EQ(resumed.rackNumber(), played.rackNumber());
  EXPECT_EQ(resumed.racksWon(0), played.racksWon(0));
  EXPECT_EQ(resumed.racksWon(1), played.racksWon(1));
  EXPECT_EQ(resumed.seatToMove(), played.seatToMove());
  EXPECT_EQ(resumed.breaks(), BreakOrder::Winner);
  EXPECT_EQ(resumed.matchTurns().size(), played.matchTurns().size());
  const auto a = played.match().balls();
  const auto b = resumed.match().balls();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].pos, b[i].pos);
  // A match file that does not come back to its rack is refused, not resumed elsewhere.
  SavedRack edited = *back;
  edited.rack_index += 1;
  GameSession wrong(setup);
  EXPECT_THROW(replayRack(wrong, edited), IllegalAction);
}

TEST_F(RackFiles, ABadFileIsNotOffered) {
  const std::string path = rackSavePath();
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  for (const char* text : {"", "{", "[]", R"({"version": 2})",
                           R"({"version": 1, "rules": "wpa", "seed": 1, "rack": 0,
                               "racks_won": [0, 0], "names": ["a", "b"], "opponent": "human",
                               "turns": [{"kind": "lob"}]})"}) {
    std::ofstream(path) << text;
    EXPECT_FALSE(loadRack(path)) << text;
  }
}

// A saved rack is checked as strictly as a match script and dropped (deleted, so that it is not
// refused again at every start) when it fails: ten-ball with the paper's rules ended the game
// with an internal error, rack 2147483647 overflowed in the menu, elevation pi was accepted.
TEST_F(RackFiles, ARackTheGameCannotPlayIsDroppedAndDeleted) {
  const std::string path = rackSavePath();
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  const std::string head = R"({"version": 1, "seed": 1, "opponent": "human", )";
  const std::string shot = R"({"kind": "shot", "heading_rad": 0.1, "speed": 10, "tip": [0, 0],
                               "elevation_rad": 0})";
  const std::vector<std::string> bad = {
      head + R"("game": "ten-ball", "rules": "paper", "rack": 0, "racks_won": [0, 0],
                "names": ["a", "b"], "turns": [])" +
          "}",
      head + R"("rules": "wpa", "rack": 2147483647, "racks_won": [0, 0], "names": ["a", "b"],
                "turns": [])" +
          "}",
      head + R"("rules": "wpa", "rack": 0, "racks_won": [5, 0], "names": ["a", "b"],
                "turns": [])" +
          "}",
      head + R"("rules": "wpa", "rack": 0, "racks_won": [0, 0], "names": ["a", "b"],
                "turns": [{"kind": "shot", "heading_rad": 0.1, "speed": 10, "tip": [0, 0],
                           "elevation_rad": 3.14159}]})",
      head + R"("rules": "wpa", "rack": 0, "racks_won": [0, 0], "names": ["a", "b"],
                "turns": [{"kind": "shot", "heading_rad": 0.1, "speed": 40, "tip": [0, 0],
                           "elevation_rad": 0}]})",
      head + R"("rules": "wpa", "rack": 0, "racks_won": [0, 0], "names": ["a", "b"],
                "turns": [{"kind": "shot", "heading_rad": 0.1, "speed": 10, "tip": [0.4, 0.4],
                           "elevation_rad": 0}]})",
      head + R"("rules": "wpa", "rack": 0, "racks_won": [0, 0], "names": ["", "b"],
                "turns": [)" +
          shot + "]}",
  };
  for (const std::string& text : bad) {
    std::ofstream(path) << text;
    EXPECT_FALSE(loadRack(path)) << text;
    EXPECT_FALSE(std::filesystem::exists(path)) << "kept: " << text;
  }
  std::ofstream(path) << head + R"("rules": "wpa", "rack": 3, "racks_won": [2, 1],
                                  "names": ["a", "b"], "turns": [)" +
                             shot + "]}";
  EXPECT_TRUE(loadRack(path));
}

TEST_F(RackFiles, ANameIsCutOnACharacterBoundary) {
  const std::string path = rackSavePath();
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  const std::string long_name = std::string(23, 'a') + "\xc3\xa9";  // 23 + a 2-byte character
  std::ofstream(path) << R"({"version": 1, "seed": 1, "opponent": "human", "rules": "wpa",
      "rack": 0, "racks_won": [0, 0], "turns": [], "names": [")" +
                             long_name + R"(", "b"]})";
  const auto rack = loadRack(path);
  ASSERT_TRUE(rack);
  EXPECT_EQ(rack->names[0], std::string(23, 'a'));
  EXPECT_NO_THROW(rackToJson(*rack).dump());
}

}  // namespace
}  // namespace nineball::window

namespace nineball::window {
namespace {

TEST(RackSaveTurns, SnookersNominationsAndReplaceAfterAMissAreKept) {
  // A snooker rack: a colour nominated (ball 19, the blue) and the balls replaced after a miss;
  // both read back as played, so the rack resumes where it was.
  SavedRack rack;
  rack.game = rules::Game::Snooker;
  rack.rules = rules::RuleSet::Wpbsa;
  TurnInput nominated;
  nominated.shot = Shot::withSpeed(10.0, 2.0);
  nominated.call = rules::Call{19, PocketId::TopRight};
  TurnInput replace;
  replace.kind = TurnInput::Kind::Decision;
  replace.shoot = false;
  replace.replace = true;
  rack.turns = {nominated, replace};
  std::string why;
  const auto back = rackFromJson(nlohmann::json::parse(rackToJson(rack).dump()), why);
  ASSERT_TRUE(back) << why;
  ASSERT_EQ(back->turns.size(), 2u);
  ASSERT_TRUE(back->turns[0].call);
  EXPECT_EQ(back->turns[0].call->ball, 19);
  EXPECT_TRUE(back->turns[1].replace);
  EXPECT_FALSE(back->turns[1].shoot);
}

}  // namespace
}  // namespace nineball::window
