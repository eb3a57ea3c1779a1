// The start menu and the settings screen as a state machine: keys, text, clicks, the choice.
#include "window/menu.hpp"

#include <gtest/gtest.h>

#include "window/menu_rows.hpp"

namespace nineball::window {
namespace {

void selectRow(MenuModel& m, const std::string& label) {
  const int want = rowNamed(m, label);
  ASSERT_GE(want, 0) << label;
  for (int i = 0; i < 20 && m.selected() != want; ++i) m.key(MenuKey::Down);
  ASSERT_EQ(m.selected(), want) << label;
}

TEST(Menu, StartsOnPlayAndSkipsWhatIsGreyed) {
  MenuModel m(Settings{}, std::nullopt);
  EXPECT_EQ(m.screen(), MenuModel::Screen::Main);
  EXPECT_EQ(m.rows()[m.selected()].label, "Play nine-ball");
  EXPECT_TRUE(m.rows()[rowNamed(m, "Practice")].enabled);
  EXPECT_FALSE(m.rows()[rowNamed(m, "Computer level")].enabled);
  m.key(MenuKey::Down);
  EXPECT_EQ(m.rows()[m.selected()].label, "Practice");
  m.key(MenuKey::Down);
  EXPECT_EQ(m.rows()[m.selected()].label, "Opponent");
  m.key(MenuKey::Up);
  m.key(MenuKey::Up);
  EXPECT_EQ(m.rows()[m.selected()].label, "Play nine-ball");
  m.key(MenuKey::Up);  // round to the bottom
  EXPECT_EQ(m.rows()[m.selected()].label, "Quit");
}

TEST(Menu, PracticeIsAGameModeOfItsOwn) {
  MenuModel m(Settings{}, std::nullopt);
  selectRow(m, "Practice");
  m.key(MenuKey::Enter);
  ASSERT_EQ(m.outcome(), MenuModel::Outcome::Play);
  EXPECT_EQ(m.choice().mode, GameMode::Practice);
  EXPECT_EQ(m.settings().last.mode, GameMode::Practice);
}

TEST(Menu, ChoosesTheComputerItsLevelAndTheRules) {
  MenuModel m(Settings{}, std::nullopt);
  selectRow(m, "Opponent");
  m.key(MenuKey::Right);
  EXPECT_EQ(m.rows()[m.selected()].value, "Computer");
  EXPECT_TRUE(m.rows()[rowNamed(m, "Computer level")].enabled);
  EXPECT_FALSE(m.rows()[rowNamed(m, "Player 2 name")].enabled);
  selectRow(m, "Computer level");
  EXPECT_EQ(m.rows()[m.selected()].value, "Club");
  m.key(MenuKey::Left);
  m.key(MenuKey::Left);
  m.key(MenuKey::Left);
  EXPECT_EQ(m.rows()[m.selected()].value, "Master") << "the levels go round";
  selectRow(m, "Rules");
  m.key(MenuKey::Enter);
  EXPECT_EQ(m.rows()[m.selected()].value.substr(0, 5), "Paper");
  selectRow(m, "Play nine-ball");
  m.key(MenuKey::Enter);
  ASSERT_EQ(m.outcome(), MenuModel::Outcome::Play);
  const MenuChoice c = m.choice();
  EXPECT_EQ(c.mode, GameMode::Match);
  EXPECT_EQ(c.opponent, Seat(ComputerSeat{ai::Level::Master}));
  EXPECT_EQ(c.rules, rules::RuleSet::Paper);
  EXPECT_FALSE(c.resume);
  // The settings keep the choice for the next start.
  EXPECT_EQ(m.settings().last.opponent, Seat(ComputerSeat{ai::Level::Master}));
  EXPECT_EQ(m.settings().last.rules, rules::RuleSet::Paper);
}

TEST(Menu, NamesAreTypedWithTheKeyboard) {
  MenuModel m(Settings{}, std::nullopt);
  selectRow(m, "Player 1 name");
  m.text(U'x');  // not editing yet: ignored
  EXPECT_EQ(m.rows()[m.selected()].value, "Player 1");
  m.key(MenuKey::Enter);
  ASSERT_TRUE(m.editing());
  EXPECT_TRUE(m.rows()[m.selected()].editing);
  for (int i = 0; i < 8; ++i) m.key(MenuKey::Backspace);
  for (char32_t c : std::u32string(U"Ann \u00e9\u2603")) m.text(c);
  m.text(U'\r');  // control characters are keys, not text
  m.text(0x7F);
  m.key(MenuKey::Backspace);  // erases the whole snowman, three bytes
  m.key(MenuKey::Enter);
  EXPECT_FALSE(m.editing());
  EXPECT_EQ(m.choice().names[0], "Ann \u00e9");
  // An emptied name comes back as the seat's.
  selectRow(m, "Player 2 name");
  m.key(MenuKey::Enter);
  for (int i = 0; i < 20; ++i) m.key(MenuKey::Backspace);
  m.key(MenuKey::Escape);
  EXPECT_EQ(m.choice().names[1], "Player 2");
  EXPECT_EQ(m.outcome(), MenuModel::Outcome::None);  // Esc ended the edit, not the menu
  // Names have a limit.
  m.key(MenuKey::Enter);
  for (int i = 0; i < 100; ++i) m.text(U'w');
  m.key(MenuKey::Enter);
  EXPECT_LE(m.choice().names[1].size(), 24u);
}

TEST(Menu, ResumeComesFirstWhenARackIsSaved) {
  MenuModel m(Settings{}, std::string("Ann vs Bob: rack 2, racks 1-0"));
  EXPECT_EQ(m.rows()[0].label, "Resume rack");
  EXPECT_EQ(m.rows()[0].value, "Ann vs Bob: rack 2, racks 1-0");
  EXPECT_EQ(m.selected(), 0);
  m.key(MenuKey::Enter);
  EXPECT_EQ(m.outcome(), MenuModel::Outcome::Resume);
  EXPECT_TRUE(m.choice().resume);
}

TEST(Menu, TheSettingsScreenEditsTheSettings) {
  Settings s;
  s.last.opponent = ComputerSeat{ai::Level::Casual};
  MenuModel m(s, std::nullopt);
  EXPECT_EQ(m.choice().opponent,
            Seat(ComputerSeat{ai::Level::Casual}));  // preset from the last game
  selectRow(m, "Settings");
  m.key(MenuKey::Enter);
  ASSERT_EQ(m.screen(), MenuModel::Screen::Settings);
  EXPECT_EQ(m.rows()[m.selected()].label, "Volume");
  m.key(MenuKey::Right);
  EXPECT_EQ(m.settings().volume, 90);
  for (int i = 0; i < 5; ++i) m.key(MenuKey::Right);
  EXPECT_EQ(m.settings().volume, 100);
  m.key(MenuKey::Down);
  m.key(MenuKey::Enter);
  EXPECT_TRUE(m.settings().muted);
  m.key(MenuKey::Down);
  m.key(MenuKey::Left);
  EXPECT_EQ(m.settings().guide, GuideLength::Short);
  m.key(MenuKey::Down);
  m.key(MenuKey::Right);
  EXPECT_TRUE(m.settings().bank_line);
  m.key(MenuKey::Down);
  std::vector<int> caps;
  for (int i = 0; i < 5; ++i) {
    m.key(MenuKey::Right);
    caps.push_back(m.settings().frame_cap);
  }
  EXPECT_EQ(caps, (std::vector<int>{120, 240, 0, 30, 60}));
  m.key(MenuKey::Escape);
  EXPECT_EQ(m.screen(), MenuModel::Screen::Main);
  EXPECT_EQ(m.outcome(), MenuModel::Outcome::None);
  m.key(MenuKey::Escape);
  EXPECT_EQ(m.outcome(), MenuModel::Outcome::Quit);
}

TEST(Menu, TheSettingsAloneCloseWithBackOrEscape) {
  MenuModel m = MenuModel::settingsOnly(Settings{});
  EXPECT_EQ(m.screen(), MenuModel::Screen::Settings);
  m.key(MenuKey::Escape);
  EXPECT_EQ(m.outcome(), MenuModel::Outcome::Close);
  MenuModel n = MenuModel::settingsOnly(Settings{});
  n.click(static_cast<int>(n.rows().size()) - 1);
  EXPECT_EQ(n.outcome(), MenuModel::Outcome::Close);
}

TEST(Menu, ThePointerSelectsAndClicks) {
  MenuModel m(Settings{}, std::nullopt);
  const int rules = rowNamed(m, "Rules");
  m.hover(rules);
  EXPECT_EQ(m.selected(), rules);
  m.hover(rowNamed(m, "Computer level"));  // greyed with no computer: stays
  EXPECT_EQ(m.selected(), rules);
  m.hover(-1);
  EXPECT_EQ(m.selected(), rules);
  m.click(rules);
  EXPECT_EQ(m.choice().rules, rules::RuleSet::Paper);
  m.click(rowNamed(m, "Player 1 name"));
  EXPECT_TRUE(m.editing());
  m.click(rowNamed(m, "Quit"));  // ends the edit and quits
  EXPECT_FALSE(m.editing());
  EXPECT_EQ(m.outcome(), MenuModel::Outcome::Quit);
}

TEST(Menu, TheSoundRowSaysOffWhenStartedWithMute) {
  MenuModel m = MenuModel::settingsOnly(Settings{});  // the file says sound on
  m.setMutedByOption(true);
  const MenuRow sound = m.rows()[rowNamed(m, "Sound (M)")];
  EXPECT_EQ(sound.value, "Off this run (--mute)");
  EXPECT_FALSE(sound.enabled);
}

// Snooker is played in frames: a Frames row sets the match's length, best of 1 to 11, kept in
// the settings; a game without frames has no such row.
TEST(Menu, ARaceChoosesWhoBreaksTheRacksAfterTheFirst) {
  MenuModel m(Settings{}, std::nullopt);
  const int breaks = rowNamed(m, "Break");
  ASSERT_GE(breaks, 0);
  EXPECT_FALSE(m.rows()[breaks].enabled) << "racks without end: each seat breaks in turn";
  selectRow(m, "Match");
  m.key(MenuKey::Right);
  EXPECT_EQ(m.rows()[m.selected()].value, "Race to 3 racks");
  ASSERT_TRUE(m.rows()[breaks].enabled);
  EXPECT_EQ(m.rows()[breaks].value, "In turn (WPA standard)");
  selectRow(m, "Break");
  m.key(MenuKey::Right);
  EXPECT_EQ(m.rows()[breaks].value, "Winner of the last rack");
  EXPECT_EQ(m.choice().breaks, BreakOrder::Winner);
  // Kept with the settings for the next start.
  std::string warnings;
  const Settings back =
      settingsFromJson(nlohmann::json::parse(settingsToJson(m.settings()).dump()), warnings);
  EXPECT_EQ(back.last.breaks, BreakOrder::Winner);
  EXPECT_TRUE(warnings.empty());
}

TEST(Menu, SnookerChoosesTheMatchLengthInFrames) {
  MenuModel m(Settings{}, std::nullopt);
  EXPECT_EQ(rowNamed(m, "Frames"), -1);
  EXPECT_EQ(m.choice().best_of, 0);
  selectRow(m, "Game");
  for (int i = 0; i < 10 && m.rows()[m.selected()].value != "Snooker"; ++i) m.key(MenuKey::Right);
  ASSERT_EQ(m.rows()[m.selected()].value, "Snooker");
  ASSERT_GE(rowNamed(m, "Frames"), 0);
  EXPECT_EQ(m.rows()[rowNamed(m, "Frames")].value, "Best of 1 (first to 1)");
  selectRow(m, "Frames");
  m.key(MenuKey::Right);
  m.key(MenuKey::Right);
  EXPECT_EQ(m.rows()[m.selected()].value, "Best of 5 (first to 3)");
  m.key(MenuKey::Left);
  m.key(MenuKey::Left);
  m.key(MenuKey::Left);
  EXPECT_EQ(m.rows()[m.selected()].value, "Best of 11 (first to 6)") << "the lengths go round";
  m.key(MenuKey::Enter);  // a choice moves on with Enter too
  EXPECT_EQ(m.rows()[m.selected()].value, "Best of 1 (first to 1)");
  m.key(MenuKey::Right);
  selectRow(m, "Play snooker");
  m.key(MenuKey::Enter);
  ASSERT_EQ(m.outcome(), MenuModel::Outcome::Play);
  EXPECT_EQ(m.choice().best_of, 3);
  EXPECT_EQ(m.settings().last.best_of, 3);
  // The next start offers the length chosen last; a saved length no longer offered is not.
  EXPECT_EQ(MenuModel(m.settings(), std::nullopt).choice().best_of, 3);
  Settings odd = m.settings();
  odd.last.best_of = 4;
  EXPECT_EQ(MenuModel(odd, std::nullopt).choice().best_of, 1);
}

TEST(Menu, PlayOnlineOpensAScreenToHostOrJoin) {
  MenuModel m(Settings{}, std::nullopt);
  selectRow(m, "Play online: host / join");
  m.key(MenuKey::Enter);
  ASSERT_EQ(m.screen(), MenuModel::Screen::Online);
  EXPECT_EQ(m.title(), "Play online");
  EXPECT_EQ(m.rows()[m.selected()].label, "Host");
  // Nothing to join before an address is typed.
  EXPECT_FALSE(m.rows()[rowNamed(m, "Join")].enabled);
  m.key(MenuKey::Escape);
  EXPECT_EQ(m.screen(), MenuModel::Screen::Main);
  EXPECT_EQ(m.outcome(), MenuModel::Outcome::None);
}

TEST(Menu, HostingStartsTheGameChosenWithAPersonInTheOtherSeat) {
  Settings s;
  s.last.opponent = ComputerSeat{ai::Level::Club};
  MenuModel m(s, std::nullopt);
  selectRow(m, "Play online: host / join");
  m.key(MenuKey::Enter);
  m.key(MenuKey::Enter);  // Host
  ASSERT_EQ(m.outcome(), MenuModel::Outcome::Host);
  EXPECT_EQ(m.choice().mode, GameMode::Match);
  EXPECT_TRUE(std::holds_alternative<HumanSeat>(m.choice().opponent));
}

TEST(Menu, TheAddressIsTypedRememberedAndJoined) {
  MenuModel m(Settings{}, std::nullopt);
  selectRow(m, "Play online: host / join");
  m.key(MenuKey::Enter);
  selectRow(m, "Friend's address");
  m.key(MenuKey::Enter);
  ASSERT_TRUE(m.editing());
  for (char32_t c : std::u32string(U"10.0.0.7 :47047\u00e9")) m.text(c);  // no space, ASCII only
  m.key(MenuKey::Enter);
  EXPECT_EQ(m.settings().join_address, "10.0.0.7:47047");
  ASSERT_TRUE(m.rows()[rowNamed(m, "Join")].enabled);
  EXPECT_EQ(m.rows()[rowNamed(m, "Join")].value, "10.0.0.7:47047");
  selectRow(m, "Join");
  m.key(MenuKey::Enter);
  EXPECT_EQ(m.outcome(), MenuModel::Outcome::Join);
  // A bad port leaves Join greyed.
  MenuModel bad(m.settings(), std::nullopt);
  selectRow(bad, "Play online: host / join");
  bad.key(MenuKey::Enter);
  selectRow(bad, "Friend's address");
  bad.key(MenuKey::Enter);
  bad.text(U'9');
  bad.key(MenuKey::Enter);
  EXPECT_FALSE(bad.rows()[rowNamed(bad, "Join")].enabled);
}

// The Join screen has a field for the host's join code: letters, digits and dashes only.
TEST(Menu, TheJoinScreenTakesTheHostsJoinCode) {
  MenuModel m(Settings{}, std::nullopt);
  selectRow(m, "Play online: host / join");
  m.key(MenuKey::Enter);
  selectRow(m, "Join code");
  m.key(MenuKey::Enter);
  ASSERT_TRUE(m.editing());
  for (char32_t c : std::u32string(U"7kq4 -ZP2M\u00e9!")) m.text(c);
  m.key(MenuKey::Enter);
  EXPECT_EQ(m.settings().join_code, "7kq4-ZP2M");
  EXPECT_EQ(m.rows()[rowNamed(m, "Join code")].value, "7kq4-ZP2M");
}

}  // namespace
}  // namespace nineball::window
