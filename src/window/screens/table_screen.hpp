#pragma once

#include "window/screens/screen.hpp"

namespace nineball::window {

/// The match on the table as the window plays it (GameLoop holds the session, its seats and
/// input, the online game and the painter).
class Table {
 public:
  virtual ~Table() = default;
  /// One window event for the game: the input, F2's settings, the sound's key.
  virtual void tableEvent(const sf::Event& event) = 0;
  /// One frame of play; `on_top` is false while the settings lie over the table (the computer
  /// waits then, as for a dialog).
  virtual void advanceTable(double seconds, bool on_top) = 0;
  virtual void drawTable(sf::RenderTarget& target) = 0;
  /// True while a ball rolls, a player or the computer plays, a key is held or the game is
  /// online: the frames go on without waiting for an event.
  virtual bool tableBusy() const = 0;
};

/// The table: the bottom screen, always there; the start menu and the settings lie over it.
class TableScreen : public Screen {
 public:
  explicit TableScreen(Table& table) : table_(table) {}

  void event(const sf::Event& event) override { table_.tableEvent(event); }
  void update(double seconds, bool on_top) override { table_.advanceTable(seconds, on_top); }
  void draw(sf::RenderTarget& target) override { table_.drawTable(target); }
  bool covers() const override { return true; }
  bool busy() const override { return table_.tableBusy(); }
  bool finished() const override { return false; }

 private:
  Table& table_;
};

}  // namespace nineball::window
