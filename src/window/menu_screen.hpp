#pragma once

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Window/Event.hpp>
#include <functional>
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

/// Shows the menu until it has an outcome or the window closes (then Quit). Draws only when
/// something changed (and every 2 s), sleeping between looks at the events, so that an
/// idle menu costs next to no processor. `background` draws what is behind the panel;
/// `resized` is told the window's new size.
MenuModel::Outcome runMenuScreen(sf::RenderWindow& window, MenuModel& model,
                                 render::MenuPainter& painter,
                                 const std::function<void(sf::RenderTarget&)>& background,
                                 const std::function<void(double, double)>& resized);

}  // namespace nineball::window
