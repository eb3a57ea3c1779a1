#pragma once

#include <memory>

namespace nineball::window {

/// A connection to the X display, held open while the game runs.
class DisplayConnection {
 public:
  /// Connects to $DISPLAY; check connected() before opening a window (SFML aborts the
  /// program when it cannot).
  DisplayConnection();
  ~DisplayConnection();
  DisplayConnection(const DisplayConnection&) = delete;
  DisplayConnection& operator=(const DisplayConnection&) = delete;

  bool connected() const { return display_ != nullptr; }

 private:
  // An X server resets when its last client leaves, and refuses connections while it does:
  // a probe that disconnected at once could make SFML's own connection, a moment later,
  // fail. So the probe stays connected until the window has its own connection.
  void* display_ = nullptr;
};

}  // namespace nineball::window
