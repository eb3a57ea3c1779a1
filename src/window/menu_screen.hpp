#pragma once

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Window/Event.hpp>
#include <optional>
#include <string>
#include <vector>

#include "render/menu_painter.hpp"
#include "window/menu.hpp"

namespace nineball::window {

/// "down,right,enter" as the menu's keys (up, down, left, right, enter, escape, backspace, tab);
/// nothing, with `why`, for a word that names none.
std::optional<std::vector<MenuKey>> parseMenuKeys(const std::string& text, std::string& why);

/// What the painter draws for the model now.
render::MenuPicture menuPicture(const MenuModel& model);

/// Gives one window event to the menu of a `width` x `height` window; true when it may have
/// changed what the menu shows.
bool handleMenuEvent(MenuModel& model, const sf::Event& event, double width, double height);

}  // namespace nineball::window
