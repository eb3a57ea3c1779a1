#pragma once

#include <SFML/Window/Window.hpp>

namespace nineball::window {

/// Gives the window nineball's icon (resources/nineball-256.png, found by findResourceDir).
/// A missing or unreadable icon is logged as a warning and the window keeps the desktop's
/// default: an icon is never worth failing for. Called again whenever the window is
/// recreated, which drops the icon.
void setWindowIcon(sf::Window& window);

}  // namespace nineball::window
