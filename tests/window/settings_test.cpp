// The settings file: round trip, bad files, where it lives.
#include "window/settings.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace nineball::window {
namespace {

// A fresh directory for XDG_CONFIG_HOME (and HOME), restored after the test.
class SettingsFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("nineball-settings-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    for (const char* name : {"XDG_CONFIG_HOME", "HOME"}) {
      const char* v = std::getenv(name);
      saved_.push_back(v ? std::optional<std::string>(v) : std::nullopt);
    }
    setenv("XDG_CONFIG_HOME", (dir_ / "config").c_str(), 1);
    setenv("HOME", (dir_ / "home").c_str(), 1);
  }
  void TearDown() override {
    const char* names[] = {"XDG_CONFIG_HOME", "HOME"};
    for (int i = 0; i < 2; ++i) {
      if (saved_[i]) {
        setenv(names[i], saved_[i]->c_str(), 1);
      } else {
        unsetenv(names[i]);
      }
    }
    std::filesystem::remove_all(dir_);
  }
  void write(const std::string& text) {
    std::filesystem::create_directories(std::filesystem::path(settingsPath()).parent_path());
    std::ofstream(settingsPath()) << text;
  }

  std::filesystem::path dir_;
  std::vector<std::optional<std::string>> saved_;
};

TEST_F(SettingsFiles, LiveUnderXdgConfigHomeElseUnderHomeDotConfig) {
  EXPECT_EQ(settingsPath(), (dir_ / "config" / "nineball" / "settings.json").string());
  unsetenv("XDG_CONFIG_HOME");
  EXPECT_EQ(settingsPath(), (dir_ / "home" / ".config" / "nineball" / "settings.json").string());
  // A relative XDG path is ignored, as the specification says.
  setenv("XDG_CONFIG_HOME", "relative/dir", 1);
  EXPECT_EQ(settingsPath(), (dir_ / "home" / ".config" / "nineball" / "settings.json").string());
  unsetenv("HOME");
  EXPECT_EQ(settingsPath(), "");
  EXPECT_EQ(loadSettings(settingsPath()), Settings{});
  std::string why;
  EXPECT_FALSE(saveSettings(Settings{}, settingsPath(), why));
  EXPECT_FALSE(why.empty());
}

TEST_F(SettingsFiles, SaveThenLoadGivesTheSameSettings) {
  Settings s;
  s.volume = 35;
  s.muted = true;
  s.guide = GuideLength::Long;
  s.bank_line = true;
  s.frame_cap = 0;
  s.last.mode = GameMode::Practice;
  s.last.opponent = ComputerSeat{ai::Level::Master};
  s.last.rules = rules::RuleSet::Paper;
  s.last.points = 40;
  s.last.best_of = 9;
  s.last.names = {"Ann \u00e9", "Bob"};
  s.join_address = "192.168.1.20:5000";
  std::string why;
  ASSERT_TRUE(saveSettings(s, settingsPath(), why)) << why;
  EXPECT_TRUE(std::filesystem::exists(dir_ / "config" / "nineball" / "settings.json"));
  EXPECT_EQ(loadSettings(settingsPath()), s);
  // Saved again over the old file: still whole, no temporary file left beside it.
  s.volume = 100;
  ASSERT_TRUE(saveSettings(s, settingsPath(), why)) << why;
  EXPECT_EQ(loadSettings(settingsPath()), s);
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir_ / "config" / "nineball")) {
    (void)e;
    ++files;
  }
  EXPECT_EQ(files, 1);
}

TEST(Settings, AnAddressToJoinThatIsNotOneIsDroppedWithAWarning) {
  std::string warnings;
  const Settings s = settingsFromJson({{"join_address", "host:99999"}}, warnings);
  EXPECT_EQ(s.join_address, "");
  EXPECT_NE(warnings.find("join_address"), std::string::npos) << warnings;
  warnings.clear();
  EXPECT_EQ(settingsFromJson({{"join_address", "friend.example"}}, warnings).join_address,
            "friend.example");
  EXPECT_EQ(warnings, "");
}

TEST_F(SettingsFiles, AMissingFileGivesTheDefaults) {
  EXPECT_EQ(loadSettings(settingsPath()), Settings{});
}

TEST_F(SettingsFiles, ABadFileGivesTheDefaultsAndNeverThrows) {
  const std::vector<std::string> texts = {"",
                                          "{",
                                          "not json",
                                          "[1, 2]",
                                          "null",
                                          "42",
                                          "\"x\"",
                                          "{\"volume\": \"loud\"}",
                                          std::string("\xff\xfe garbage", 11)};
  for (const std::string& text : texts) {
    write(text);
    Settings s;
    EXPECT_NO_THROW(s = loadSettings(settingsPath())) << text;
    EXPECT_EQ(s, Settings{}) << text;
  }
  // A directory where the file should be is no file either.
  std::filesystem::remove(settingsPath());
  std::filesystem::create_directories(settingsPath());
  EXPECT_EQ(loadSettings(settingsPath()), Settings{});
}

// A name of 39 ASCII characters and an "é" was cut at 40 bytes inside the character, and
// writing it back (Play saves the settings) ended the game with nlohmann's type_error.316.
TEST_F(SettingsFiles, ANameIsCutOnACharacterBoundaryAndSavesAgain) {
  write(R"({"last": {"names": [")" + std::string(39, 'n') + "\xc3\xa9" + R"(", "Bo"]}})");
  Settings s;
  ASSERT_NO_THROW(s = loadSettings(settingsPath()));
  EXPECT_EQ(s.last.names[0], std::string(24, 'n'));
  EXPECT_EQ(s.last.names[1], "Bo");
  std::string why;
  EXPECT_TRUE(saveSettings(s, settingsPath(), why)) << why;
  write(R"({"last": {"names": [")" + std::string(20, 'n') + "\xc3\xa9" + R"(", "Bo"]}})");
  EXPECT_EQ(loadSettings(settingsPath()).last.names[0], std::string(20, 'n') + "\xc3\xa9");
}

TEST_F(SettingsFiles, ABadFieldKeepsItsDefaultAndTheGoodOnesAreRead) {
  write(R"({"volume": 250, "muted": true, "aim_guide": "huge", "bank_line": "yes",
            "frame_cap": 144, "last": {"opponent": "ai:easy", "rules": "snooker",
            "names": ["Ann", 3]}})");
  const Settings s = loadSettings(settingsPath());
  Settings want;
  want.muted = true;
  want.last.opponent = ComputerSeat{ai::Level::Casual};
  EXPECT_EQ(s, want);
  std::string warnings;
  settingsFromJson(nlohmann::json::parse(R"({"volume": -1, "frame_cap": 240})"), warnings);
  EXPECT_NE(warnings.find("volume"), std::string::npos) << warnings;
  EXPECT_EQ(warnings.find("frame_cap"), std::string::npos) << warnings;
}

}  // namespace
}  // namespace nineball::window
