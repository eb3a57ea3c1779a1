#pragma once

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/System/Clock.hpp>
#include <SFML/Window/Event.hpp>
#include <iosfwd>
#include <memory>
#include <optional>

#include "app/game_options.hpp"
#include "audio/impact_sounds.hpp"
#include "render/fonts.hpp"
#include "render/menu_painter.hpp"
#include "render/scene_painter.hpp"
#include "render/sfml_errors.hpp"
#include "window/capture_driver.hpp"
#include "window/display_probe.hpp"
#include "window/frame_timer.hpp"
#include "window/game_input.hpp"
#include "window/game_session.hpp"
#include "window/game_window.hpp"
#include "window/menu.hpp"
#include "window/online_play.hpp"
#include "window/screens/dialog_screen.hpp"
#include "window/screens/screen_stack.hpp"
#include "window/screens/table_dialogs.hpp"
#include "window/screens/table_screen.hpp"
#include "window/seats/seats.hpp"
#include "window/session_stats.hpp"
#include "window/settings.hpp"
#include "window/start_menu.hpp"
#include "window/ui_state.hpp"

namespace nineball::window {

/// The game window from start to end. Construction sets the game up: the script's turns, the
/// display and the fonts, the window, the start menu. run() is the window's one event loop: it
/// goes round the frame for the screens on its stack (the table at the bottom, its dialogs, the
/// start menu and the settings over it): the events, the screens' frame, the picture, the
/// screenshots, the wait when nothing moves; and at the end keeps the rack in play for the next
/// start. The table's state is its screen's (TableScreen); the loop lends it the window
/// (TableWindow).
class GameLoop : private TableWindow {
 public:
  GameLoop(const app::GameOptions& options, const GameStart& start, std::ostream& err);
  GameLoop(const GameLoop&) = delete;
  GameLoop& operator=(const GameLoop&) = delete;

  /// The exit status when the setup already ended the game (see runGame: a refusal, or 0 after
  /// the start menu's screenshot or its Quit); nothing when run() is to play.
  std::optional<int> setupStatus() const { return setup_status_; }
  /// Plays frame after frame until the window closes, the screenshot is taken or the --frames
  /// are drawn; returns the exit status.
  int run();

 private:
  // The table, made with the loop and put at the bottom of its stack.
  TableScreen& makeTable(const GameStart& start);
  // The setup, in its order.
  std::optional<int> setUp(const GameStart& start);
  std::optional<int> playScript(const GameStart& start);
  std::optional<int> openDisplay();
  void readSettings(const GameStart& start);
  void openGameWindow();
  StartMenuContext menuContext();
  std::optional<int> startMenu();
  void showStartMenu();
  void menuClosed(MenuModel::Outcome outcome, bool started);
  void beginFrames();
  void prepareFrames(const GameStart& start);
  std::optional<int> startOnline(const GameStart& start);
  void startOnlineFromMenu(MenuModel::Outcome outcome);
  std::optional<CaptureDriver::OnlineEnd> onlineEnd();

  // The steps of one frame, in their order.
  bool handleEvents();
  bool waitWhileIdle(bool changed);
  void draw();
  void takeRequestedScreenshot();
  void present(bool rolling);
  void answerRequests();
  void capFrameRate();
  void backToMenu();
  int finish();

  // TableWindow: what the loop lends the table.
  render::ScenePainter& painter() override { return *painter_; }
  const render::ViewTransform& pointerView() override { return painter_->view(); }
  Settings& settings() override { return settings_; }
  ScreenStack& screens() override { return screens_; }
  audio::ImpactSounds* sounds() override { return sounds_.get(); }
  void openSettings() override;
  void applySound() override;
  void saveSettingsNow() override;

  std::ostream& err_;
  // Made in the setup's order, once the steps before them went through.
  std::optional<DisplayConnection> display_;
  std::optional<render::Fonts> fonts_;
  std::optional<render::SfmlErrorsToLog> sfml_log_;
  app::GameOptions options_;
  const CaptureDriver driver_;  // a person, a picture run or a benchmark runs the frames
  const bool show_menu_;
  const bool keep_rack_;
  const bool online_start_;  // --host or --join
  Settings settings_;
  bool fullscreen_ = false;
  std::optional<sf::RenderWindow> window_;
  std::optional<render::ScenePainter> painter_;
  std::optional<render::MenuPainter> menu_painter_;
  std::unique_ptr<audio::ImpactSounds> sounds_;
  // The table at the bottom; a dialog, the start menu or the settings over it.
  ScreenStack screens_;
  TableScreen& table_;       // the match on the table, its state and its play
  bool demo_break_ = false;  // --frames on a table with no script: a break to watch
  bool menu_open_ = false;   // the start menu lies over the table
  bool demo_due_ = false;    // --frames' demo break and --replay wait for the start menu's game
  FrameTimer moving_;
  sf::Clock frame_clock_;
  sf::Clock display_clock_;
  sf::Clock since_draw_;
  long frame_ = 0;
  std::optional<int> setup_status_;
};

}  // namespace nineball::window
