#pragma once

#include <SFML/System/Vector2.hpp>
#include <algorithm>

namespace nineball::window {

/// The top-left corner that centres a `window`-sized window on a `desktop`-sized desktop.
/// Without a window manager to place it, a window stays where it is put; one larger than the
/// desktop keeps its top-left corner (and so its title bar) on the desktop.
inline sf::Vector2i centredOnDesktop(sf::Vector2u window, sf::Vector2u desktop) {
  const auto offset = [](unsigned w, unsigned d) {
    return std::max(0, (static_cast<int>(d) - static_cast<int>(w)) / 2);
  };
  return {offset(window.x, desktop.x), offset(window.y, desktop.y)};
}

}  // namespace nineball::window
