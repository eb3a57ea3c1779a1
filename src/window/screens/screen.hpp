#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Window/Event.hpp>

namespace nineball::window {

/// One thing the window shows and the player talks to: the start menu, the table, the settings
/// over the table. Screens lie on a stack (screen_stack.hpp) that the window's one event loop
/// drives: the top screen takes the events; the screens from the top down to the first that
/// covers the rest are updated, and drawn from that one up. Adding a screen is one more class
/// in this folder and a push where it opens.
class Screen {
 public:
  virtual ~Screen() = default;

  /// One window event (the loop itself answers closing and resizing the window).
  virtual void event(const sf::Event& event) = 0;
  /// One frame of `seconds`; `on_top` is false while another screen lies over this one.
  virtual void update(double seconds, bool on_top) = 0;
  /// Draws the screen over what is beneath it.
  virtual void draw(sf::RenderTarget& target) = 0;
  /// True when the screens beneath are neither drawn nor updated.
  virtual bool covers() const = 0;
  /// True while something moves or someone plays: the loop draws every frame instead of
  /// waiting for an event.
  virtual bool busy() const { return false; }
  /// True once the screen is done: the loop takes it off the stack and tells it closed().
  virtual bool finished() const = 0;
  /// Called once, after the screen left the stack: what its end means (a game chosen, the
  /// settings saved) happens here.
  virtual void closed() {}
};

}  // namespace nineball::window
