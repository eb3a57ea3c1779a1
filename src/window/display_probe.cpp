#include "window/display_probe.hpp"

#include <X11/Xlib.h>

#include <cstdlib>

namespace nineball::window {

DisplayConnection::DisplayConnection() {
  const char* name = std::getenv("DISPLAY");
  if (name != nullptr && *name != '\0') display_ = XOpenDisplay(nullptr);
}

DisplayConnection::~DisplayConnection() {
  if (display_ != nullptr) XCloseDisplay(static_cast<Display*>(display_));
}

}  // namespace nineball::window
