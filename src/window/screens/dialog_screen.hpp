#pragma once

#include <SFML/Window/Keyboard.hpp>
#include <memory>

#include "nineball/vec2.hpp"
#include "window/screens/dialog_contents.hpp"
#include "window/screens/screen.hpp"
#include "window/screens/screen_stack.hpp"

namespace nineball::window {

/// Which of a dialog's buttons lies under the pointer.
enum class DialogButton { None, Left, Middle, Right };

/// What a dialog over the table asks of it (TableDialogs answers): which dialog the game's state
/// calls for, where its buttons lie, the answers, and the table's own handling of every event
/// (its window keys, the pointer and the held keys go on while a dialog is open).
class DialogTable {
 public:
  virtual ~DialogTable() = default;
  /// The dialog the table's state calls for now (DialogKind::None: none).
  virtual DialogKind dialogWanted() const = 0;
  /// True while the computer or the player online has the table: theirs is the choice.
  virtual bool othersDecide() const = 0;
  virtual DialogButton buttonAt(Vec2 px) const = 0;
  /// The event as the table takes it under any dialog (given before the dialog answers it).
  virtual void passDown(const sf::Event& event) = 0;
  /// Draws the dialog's panel over the table as drawn this frame.
  virtual void drawDialog(sf::RenderTarget& target) = 0;
  // The answers.
  virtual void closeHelp() = 0;
  virtual void closeQuestion() = 0;  ///< the quit question's No
  virtual void leave() = 0;          ///< its Yes: to the menu, or out of the program
  virtual void decide(bool shoot_now, bool replace) = 0;
  virtual void rematch() = 0;
  virtual void quit() = 0;  ///< the rack's end's Quit
};

/// A dialog over the table (help, the quit question, the push-out choice, the rack's end): it
/// covers nothing, takes the keys and the clicks that answer it, and leaves when the table's
/// state no longer calls for it (the table's DialogSlot swaps it for the next).
class DialogScreen : public Screen {
 public:
  DialogScreen(DialogTable& table, DialogKind kind) : table_(table), kind_(kind) {}

  DialogKind kind() const { return kind_; }
  void event(const sf::Event& event) override;
  void update(double, bool) override {}
  void draw(sf::RenderTarget& target) override { table_.drawDialog(target); }
  bool covers() const override { return false; }
  bool finished() const override { return table_.dialogWanted() != kind_; }

 protected:
  /// A key pressed while the dialog is up.
  virtual void key(sf::Keyboard::Key code) = 0;
  /// A left press: on one of its buttons or beside them.
  virtual void click(DialogButton button) = 0;
  DialogTable& table() { return table_; }

 private:
  DialogTable& table_;
  const DialogKind kind_;
};

/// H: the keys and what they do. H, Esc or its button close it.
class HelpScreen : public DialogScreen {
 public:
  explicit HelpScreen(DialogTable& table) : DialogScreen(table, DialogKind::Help) {}

 private:
  void key(sf::Keyboard::Key code) override;
  void click(DialogButton button) override;
};

/// Esc when leaving would lose the rack: Y or Enter leaves, N or Esc plays on.
class QuitScreen : public DialogScreen {
 public:
  explicit QuitScreen(DialogTable& table) : DialogScreen(table, DialogKind::ConfirmQuit) {}

 private:
  void key(sf::Keyboard::Key code) override;
  void click(DialogButton button) override;
};

/// A push-out, an illegal break, a foul (snooker's miss) or a shot not as called: the player
/// who chooses plays on (S), passes it back (P) or has the balls replaced (R, snooker).
class PushOutScreen : public DialogScreen {
 public:
  explicit PushOutScreen(DialogTable& table) : DialogScreen(table, DialogKind::PushOutChoice) {}

 private:
  void key(sf::Keyboard::Key code) override;
  void click(DialogButton button) override;
};

/// The rack's (frame's, match's) end: R or Enter plays the next, its right button quits.
class RackEndScreen : public DialogScreen {
 public:
  explicit RackEndScreen(DialogTable& table) : DialogScreen(table, DialogKind::GameOver) {}

 private:
  void key(sf::Keyboard::Key code) override;
  void click(DialogButton button) override;
};

/// The one dialog over the table: the one its state calls for, lying just above the table
/// (beneath the settings or the start menu when they are open).
class DialogSlot {
 public:
  /// Puts the dialog the table calls for in place of the one shown, when they differ.
  void follow(ScreenStack& screens, DialogTable& table);
  /// True when the dialog is the screen on top (the table's play goes on beneath the push-out
  /// choice and the rack's end, as beneath no dialog).
  bool onTop(ScreenStack& screens) const;

 private:
  const DialogScreen* shown_ = nullptr;
};

/// The dialog screen of a kind (none for DialogKind::None).
std::unique_ptr<DialogScreen> makeDialog(DialogKind kind, DialogTable& table);

}  // namespace nineball::window
