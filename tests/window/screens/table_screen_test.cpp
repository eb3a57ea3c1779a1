// The table as the bottom screen: it holds the match and plays it, opens what lies over it
// (F2's settings through the window, its dialogs on the stack), and the keys go to whichever
// screen is on top: the help's H closes the help, the table's H opens it. (Drawing is left to
// the window tests: a painter needs a display.)
#include "window/screens/table_screen.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "window/game_rolling.hpp"
#include "window/input_events.hpp"
#include "window/screens/window_stand_in.hpp"

namespace nineball::window {
namespace {

// A table at the bottom of the stand-in window's stack.
struct TableOnStack {
  explicit TableOnStack(bool muted_by_option = false) {
    auto screen =
        std::make_unique<TableScreen>(MatchSetup{}, false, false, muted_by_option, window);
    table = screen.get();
    window.screens().push(std::move(screen));
  }
  // A key pressed and let go, given to the top screen as the loop does, then the loop's tidying.
  void press(sf::Keyboard::Key code) {
    for (const sf::Event& e : {key(code), release(code)}) {
      window.screens().event(e);
      window.screens().removeFinished();
      table->followDialog();
    }
  }
  DialogKind topDialog() {
    const auto* dialog = dynamic_cast<const DialogScreen*>(&window.screens().top());
    return dialog ? dialog->kind() : DialogKind::None;
  }
  test::WindowStandIn window;
  TableScreen* table = nullptr;
};

TEST(TableScreen, F2AsksTheWindowForTheSettingsAndMTurnsTheSoundAndKeepsIt) {
  TableOnStack t;
  t.press(sf::Keyboard::F2);
  EXPECT_EQ(t.window.settings_opened, 1);
  const bool muted = t.window.settings().muted;
  t.press(sf::Keyboard::M);
  EXPECT_NE(t.window.settings().muted, muted);
  EXPECT_EQ(t.window.sound_applied, 1);
  EXPECT_EQ(t.window.settings_saved, 1);
}

TEST(TableScreen, MUnderMuteOnlySaysWhy) {
  TableOnStack t(true);
  const bool muted = t.window.settings().muted;
  t.press(sf::Keyboard::M);
  EXPECT_EQ(t.window.settings().muted, muted);
  EXPECT_EQ(t.window.sound_applied, 0);
  EXPECT_NE(t.table->session().message().find("--mute"), std::string::npos);
}

TEST(TableScreen, HOpensTheHelpOverTheTableAndTheHelpOnTopTakesTheNextH) {
  TableOnStack t;
  t.press(sf::Keyboard::H);
  EXPECT_EQ(t.window.screens().size(), 2u);
  EXPECT_EQ(t.topDialog(), DialogKind::Help);
  t.press(sf::Keyboard::H);  // the help's key now, not the table's
  EXPECT_EQ(t.window.screens().size(), 1u);
  EXPECT_FALSE(t.table->ui().help);
}

TEST(TableScreen, EscWithARackInPlayAsksAndTheQuestionAnswersN) {
  TableOnStack t;
  ASSERT_TRUE(t.table->session().shoot());
  ASSERT_TRUE(roll(t.table->session()));
  t.press(sf::Keyboard::Escape);
  EXPECT_EQ(t.topDialog(), DialogKind::ConfirmQuit);
  t.press(sf::Keyboard::Space);  // not the question's answer: the rack is not shot meanwhile
  EXPECT_EQ(t.topDialog(), DialogKind::ConfirmQuit);
  EXPECT_EQ(t.table->session().phase(), Phase::Aiming);
  t.press(sf::Keyboard::N);
  EXPECT_EQ(t.window.screens().size(), 1u);
  EXPECT_FALSE(t.table->input().requests().quit);
}

TEST(TableScreen, AFrameCountsAsRollingOnceAndOnlyWhenTheTablePlayedIt) {
  TableOnStack t;
  ASSERT_TRUE(t.table->session().shoot());
  t.table->update(1.0 / 60.0, true);
  EXPECT_TRUE(t.table->takeRolled());
  // The next frame the menu covers the table, which does not play: not a rolling frame.
  EXPECT_FALSE(t.table->takeRolled());
}

}  // namespace
}  // namespace nineball::window
