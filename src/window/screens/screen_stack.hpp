#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "window/screens/screen.hpp"

namespace nineball::window {

/// The window's screens, bottom to top: the table at the bottom, the start menu or the
/// settings over it. The one event loop (GameLoop) gives it the frame's events, updates and
/// draws it.
class ScreenStack {
 public:
  void push(std::unique_ptr<Screen> screen) {
    screens_.push_back(std::move(screen));
    changed_ = true;
  }
  /// Puts a screen at `at` from the bottom (1: just above the table), beneath the ones there.
  void insert(std::size_t at, std::unique_ptr<Screen> screen);
  /// True while `screen` lies on the stack.
  bool holds(const Screen& screen) const;
  /// Takes `screen` off wherever it lies and tells it closed (a dialog the table no longer
  /// calls for, beneath the settings).
  void remove(const Screen& screen);
  bool empty() const { return screens_.empty(); }
  std::size_t size() const { return screens_.size(); }
  /// The screen on top (the stack must not be empty).
  Screen& top() { return *screens_.back(); }

  /// Gives the event to the screen on top.
  void event(const sf::Event& event);
  /// Updates the screens in sight, top first.
  void update(double seconds);
  /// Draws the screens in sight, bottom first.
  void draw(sf::RenderTarget& target);
  /// True when a screen in sight is busy (the loop then draws every frame).
  bool busy() const;
  /// Takes the finished screens off, top first, and tells each it closed; true when one went.
  bool removeFinished();
  /// Takes the screens above the lowest `keep` off, top first, telling each it closed (the
  /// window closing under them).
  void closeDownTo(std::size_t keep);
  /// True once after a screen came or went: the picture must be drawn again at once.
  bool takeChanged() { return std::exchange(changed_, false); }

 private:
  /// The lowest screen in sight: the topmost that covers the rest, else the bottom one.
  std::size_t lowestInSight() const;
  // Takes the top screen off, then tells it (its closed() may push another).
  void closeTop();

  std::vector<std::unique_ptr<Screen>> screens_;
  bool changed_ = false;
};

}  // namespace nineball::window
