#pragma once

#include <SFML/Window/Event.hpp>
#include <map>
#include <optional>

#include "render/view_transform.hpp"
#include "window/game_session.hpp"
#include "window/seats/seats.hpp"
#include "window/ui_state.hpp"

namespace nineball::window {

/// What the window itself must do after an input.
struct WindowRequests {
  bool quit = false;
  bool menu = false;  ///< back to the start menu (the rack kept as on quitting)
  bool toggle_fullscreen = false;
  bool screenshot = false;
  bool cycle_guide = false;  ///< G: the aim guide's next style (full, cue-ball line, off)
  bool save_rack = false;    ///< F5: the rack as a match script, to play again
};

/// Turns mouse and keyboard into play: the pointer aims, a drag back sets the power and the
/// release strikes; the paper's keys (arrows, Space, T/B, H) and the rest of the scheme. While
/// the computer has the turn only the window's keys work (Esc, H, F1, F12, O). Esc and H open
/// the quit question and the help; the dialogs answer their own keys and buttons
/// (screens/dialog_screen.hpp): under one, only the window's keys and the pointer work here.
class GameInput {
 public:
  GameInput(GameSession& session, UiState& ui, Seats& seats)
      : session_(session), ui_(ui), seats_(seats) {}

  /// Handles one window event; `view` maps the pointer to the table.
  void handle(const sf::Event& event, const render::ViewTransform& view);
  /// Applies held keys over one frame of `seconds`.
  void update(double seconds);

  WindowRequests& requests() { return requests_; }
  /// True while a key is down (its repeat moves the aim, the power or the cue ball).
  bool keysHeld() const { return !held_.empty(); }

 private:
  void keyPressed(const sf::Event::KeyEvent& key);
  void trackModifiers(const sf::Event::KeyEvent& key, bool pressed);
  /// The player to move may aim now (no dialog, drag, replay or computer in the way).
  bool mayAim() const;
  /// Keeps the last aim held still for a moment: the one a click on a pocket keeps.
  void followSettledAim(double seconds);
  void mousePressed(Vec2 px, const render::ViewTransform& view);
  void mouseMoved(Vec2 px, const render::ViewTransform& view);
  void mouseReleased();
  void setTipFromIcon(Vec2 px, const render::ViewTransform& view);
  void moveCueBy(Vec2 d);
  bool dialogOpen() const;
  void switchOpponent();
  /// Z / Shift+Z: one step closer or further (1x to 4x); `at` fixes the view on that point
  /// (m), else it follows the cue ball.
  void zoomBy(int steps, std::optional<Vec2> at = std::nullopt);
  /// Shift held with the pointer moving: the locked line turned a small step per pixel.
  void fineTune(Vec2 px);
  /// Practice's own keys (1-9, U, Backspace, Y); true when the key was one of them.
  bool practiceKey(const sf::Event::KeyEvent& key);

  GameSession& session_;
  UiState& ui_;
  Seats& seats_;
  WindowRequests requests_;
  std::map<sf::Keyboard::Key, double> held_;  // key -> seconds held
  bool shift_ = false;
  bool fine_ = false;  // Ctrl or Alt held: the finest aim
  double last_heading_ = 0.0;
  double heading_still_for_ = 0.0;
  std::optional<double> settled_heading_;
  std::optional<Vec2> last_px_;  // the pointer's last pixel, for the fine-tuning's travel
};

}  // namespace nineball::window
