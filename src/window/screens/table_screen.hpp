#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "audio/impact_sounds.hpp"
#include "render/scene_painter.hpp"
#include "window/game_input.hpp"
#include "window/game_session.hpp"
#include "window/online_play.hpp"
#include "window/screens/dialog_screen.hpp"
#include "window/screens/screen.hpp"
#include "window/screens/screen_stack.hpp"
#include "window/screens/table_dialogs.hpp"
#include "window/seats/seats.hpp"
#include "window/session_stats.hpp"
#include "window/settings.hpp"
#include "window/ui_state.hpp"

namespace nineball::window {

/// What the window lends the table (GameLoop): where it draws, the settings it plays by, its
/// sound, and the stack it opens screens on.
class TableWindow {
 public:
  virtual ~TableWindow() = default;
  virtual render::ScenePainter& painter() = 0;
  /// The view the pointer is read through (the painter's, zoomed as drawn).
  virtual const render::ViewTransform& pointerView() = 0;
  virtual Settings& settings() = 0;
  virtual ScreenStack& screens() = 0;
  /// The impact sounds (nullptr: none this run).
  virtual audio::ImpactSounds* sounds() = 0;
  /// F2: the settings over the table.
  virtual void openSettings() = 0;
  /// The sound as the settings now say.
  virtual void applySound() = 0;
  /// The settings kept for the next start (when this run keeps them).
  virtual void saveSettingsNow() = 0;
};

/// The match on the table: the bottom screen, always there (the dialogs, the start menu and
/// the settings lie over it). It holds the table's state: the session, who plays each seat,
/// the input, the online game, the turns a --watch plays, the dialog the state calls for.
class TableScreen : public Screen {
 public:
  /// `keep_rack`: a finished rack's save is forgotten (a person's game); `muted_by_option`:
  /// --mute, which M cannot undo.
  TableScreen(const MatchSetup& setup, bool practice, bool keep_rack, bool muted_by_option,
              TableWindow& window);

  // Screen: the events (the table's keys, F2, M, O online, the input), one frame of play, the
  // picture.
  void event(const sf::Event& event) override;
  void update(double seconds, bool on_top) override;
  void draw(sf::RenderTarget& target) override;
  bool covers() const override { return true; }
  bool busy() const override;
  bool finished() const override { return false; }

  GameSession& session() { return session_; }
  Seats& seats() { return seats_; }
  UiState& ui() { return ui_; }
  GameInput& input() { return input_; }
  /// Writes each turn into the players' statistics (the start menu's game uses it too).
  const GameSession::TurnObserver& turnCounter() const { return count_; }
  /// The game against a player at another computer (nullptr: none).
  OnlinePlay* online() { return online_.get(); }
  /// The online game begun (the host's port opened, the seats named; `remembered_name` when
  /// the config has none), in its lobby over the table until the two sides have greeted; false,
  /// with `why`, when the host's port is taken.
  bool beginOnline(OnlineConfig config, const std::string& remembered_name, std::string& why);
  /// The online game left (`why` told to the other side), the remote seat cleared.
  void leaveOnline(const std::string& why);
  /// --watch: the script's turns to play on screen, one after another.
  void watch(std::vector<TurnInput> turns) { watched_ = std::move(turns); }
  /// The --script's setup, which F5's save keeps.
  void setScriptSetup(nlohmann::json setup) { script_setup_ = std::move(setup); }
  /// True once after a frame whose play began with the balls rolling (its time counts in the
  /// frame rate); false for a frame the table did not play (the menu over it).
  bool takeRolled() { return std::exchange(rolling_, false); }
  /// The painter (and the pointer) on the session's table, whatever changed it.
  void followTable();
  /// The dialog the table's state calls for, in its place over the table.
  void followDialog() { dialog_.follow(window_.screens(), dialogs_); }
  /// Leaving the table (Esc's menu, the window closing): the online game left with `why`, else
  /// a person's rack in play kept for the next start.
  void leave(const std::string& why);
  /// Esc's menu: the dialogs, the statistics and the rack's memory start afresh.
  void leaveForMenu();
  /// F5: the match (or the rack) as a match script in the current directory.
  void saveRackScript();

 private:
  void setOnline(std::unique_ptr<OnlinePlay> online);
  void saveRackInPlay();
  void updateOnline(double seconds);
  void playWatchedTurn(double seconds);
  void zoomView(const render::Frame& picture);

  TableWindow& window_;
  GameSession session_;
  SessionStats stats_;
  const GameSession::TurnObserver count_;
  Seats seats_;  // who plays each seat: a person here, the computer, a player online
  UiState ui_;
  GameInput input_;
  TableDialogs dialogs_;         // what the dialogs over the table ask of it
  DialogSlot dialog_;            // the dialog over the table its state calls for
  render::HudState dialog_hud_;  // the dialog as the table's picture of this frame has it
  const bool keep_rack_;
  const bool muted_by_option_;
  bool rolling_ = false;
  int forgotten_rack_ = 0;
  // --watch: the script's turns still to play on screen, and how long the balls have rested.
  std::vector<TurnInput> watched_;
  std::size_t next_watched_ = 0;
  double rested_ = 0.0;
  nlohmann::json script_setup_;
  std::unique_ptr<OnlinePlay> online_;  // the game against a player at another computer
};

}  // namespace nineball::window
