#pragma once

#include <optional>
#include <string>
#include <vector>

#include "window/menu_choice.hpp"
#include "window/settings.hpp"

namespace nineball::window {

/// The keys the menu understands (the window maps SFML's to these).
enum class MenuKey { Up, Down, Left, Right, Enter, Escape, Backspace, Tab };

/// One line of the menu as drawn.
struct MenuRow {
  enum class Kind { Action, Choice, Text };
  Kind kind = Kind::Action;
  std::string label;
  std::string value;     ///< a choice's value or a text field's text
  bool enabled = true;   ///< greyed and skipped when false
  bool editing = false;  ///< a text field taking the keyboard
};

/// The start menu and the settings screen as a state machine: rows, the selected one, what
/// the keys and clicks do, and at the end what was chosen. No SFML.
class MenuModel {
 public:
  enum class Screen { Main, Settings, Online };
  /// Host / Join: play online, hosting (on the default port) or joining settings().join_address.
  enum class Outcome { None, Play, Resume, Quit, Close, Host, Join };

  /// The start menu, its choices preset from `settings.last`; `resume` labels the saved
  /// rack's entry ("Ann vs Computer: rack 4, racks 2-1") when there is one.
  MenuModel(const Settings& settings, std::optional<std::string> resume);
  /// The settings screen alone (from the game): Back or Esc closes it.
  static MenuModel settingsOnly(const Settings& settings);
  /// --mute: the sound row says it is off for this run and cannot be changed.
  void setMutedByOption(bool muted) { muted_by_option_ = muted; }

  void key(MenuKey k);
  /// A character typed (SFML's TextEntered), for the name being edited.
  void text(char32_t c);
  /// The pointer over row `i` selects it; a click activates it (a choice moves on).
  void hover(int i);
  void click(int i);

  Screen screen() const { return screen_; }
  std::string title() const;
  std::vector<MenuRow> rows() const;
  int selected() const { return selected_; }
  bool editing() const { return editing_; }

  Outcome outcome() const { return outcome_; }
  /// What the start menu settled (valid once the outcome is Play or Resume).
  MenuChoice choice() const;
  /// The distance chosen for a game played to points (its default until one is chosen).
  int pointsToWin() const;
  /// The match length chosen for a game played in frames, best of N (its first choice until
  /// one is chosen); 0 for a game whose racks simply follow one another.
  int bestOf() const;
  /// The settings as edited (the last choice included once Play was chosen).
  const Settings& settings() const { return settings_; }

 private:
  enum class Item {
    Resume,
    Play,
    Practice,
    Versus,
    Level,
    Game,
    Rules,
    Points,
    Frames,
    Breaks,
    Name1,
    Name2,
    OpenOnline,
    Host,
    Join,
    JoinAddress,
    JoinCode,
    OpenSettings,
    Quit,
    Volume,
    Sound,
    Guide,
    Bank,
    FrameCap,
    Back
  };
  std::vector<Item> items() const;
  MenuRow row(Item item) const;
  bool enabled(Item item) const;
  bool severalRules() const;  ///< the game chosen is played by more than one rule set
  void move(int step);
  void change(Item item, int step);
  void activate(Item item);
  void selectFirst();
  /// The text field being edited: a player's name or the address to join.
  std::string& editedText();
  bool joinable() const;  ///< the address to join reads as HOST[:PORT]

  Settings settings_;
  std::optional<std::string> resume_;
  Screen screen_ = Screen::Main;
  bool settings_only_ = false;
  bool computer_ = false;
  bool muted_by_option_ = false;
  ai::Level level_ = ai::Level::Club;
  int selected_ = 0;
  bool editing_ = false;
  Outcome outcome_ = Outcome::None;
};

}  // namespace nineball::window
