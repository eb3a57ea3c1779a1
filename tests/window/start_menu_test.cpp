// The start menu's setup: the command line over the remembered choice, and the table behind it.
#include "window/start_menu.hpp"

#include <gtest/gtest.h>

#include "window/frame_builder.hpp"

namespace nineball::window {
namespace {

TEST(StartMenu, TheCommandLineWinsOverTheRememberedChoice) {
  Settings remembered;
  remembered.last.game = rules::Game::EightBall;
  remembered.last.opponent = ComputerSeat{ai::Level::Master};
  // nineball --game nine-ball --opponent human: both are the defaults, and both win.
  app::GameOptions options;
  options.game_given = true;
  options.opponent_given = true;
  MatchSetup setup;
  setup.setGame(rules::Game::NineBall);
  Settings s = remembered;
  presetFromCommandLine(s, options, setup);
  EXPECT_EQ(s.last.game, rules::Game::NineBall);
  EXPECT_EQ(s.last.opponent, Seat(HumanSeat{}));
  // Options not given leave the remembered choice alone.
  Settings kept = remembered;
  presetFromCommandLine(kept, app::GameOptions{}, setup);
  EXPECT_EQ(kept.last.game, rules::Game::EightBall);
  EXPECT_EQ(kept.last.opponent, Seat(ComputerSeat{ai::Level::Master}));
}

TEST(StartMenu, TheBandBehindTheMenuSaysWhoPlaysAsTheMenuChooses) {
  Settings settings;
  settings.last.opponent = ComputerSeat{ai::Level::Casual};
  const MenuModel model(settings, std::nullopt);
  render::Frame behind;
  behind.hud.mode = opponentModeLabel(HumanSeat{});  // the session still has two players
  const render::Frame shown = menuBackdrop(behind, model);
  EXPECT_EQ(shown.hud.mode, opponentModeLabel(ComputerSeat{ai::Level::Casual}));
  EXPECT_NE(shown.hud.mode, behind.hud.mode);
}

}  // namespace
}  // namespace nineball::window
