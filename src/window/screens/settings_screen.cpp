#include "window/screens/settings_screen.hpp"

#include "window/menu_screen.hpp"

namespace nineball::window {
namespace {

// A press of `key` (named apart from game_loop.cpp's helper: one unity build unit may hold both).
bool isPressOf(const sf::Event& event, sf::Keyboard::Key key) {
  return event.type == sf::Event::KeyPressed && event.key.code == key;
}

}  // namespace

SettingsScreen::SettingsScreen(const Settings& settings, bool muted_by_option,
                               const sf::Window& window, render::MenuPainter& painter, Hooks hooks)
    : model_(MenuModel::settingsOnly(settings)),
      window_(window),
      painter_(painter),
      hooks_(std::move(hooks)) {
  model_.setMutedByOption(muted_by_option);
}

void SettingsScreen::event(const sf::Event& event) {
  if (isPressOf(event, sf::Keyboard::F2)) model_.key(MenuKey::Escape);
  if (isPressOf(event, sf::Keyboard::F12)) hooks_.screenshot();
  // A key held when the settings opened is still let go in the game.
  if (event.type == sf::Event::KeyReleased || event.type == sf::Event::LostFocus) {
    hooks_.let_go(event);
  }
  handleMenuEvent(model_, event, window_.getSize().x, window_.getSize().y);
  hooks_.changed(model_.settings());
}

void SettingsScreen::draw(sf::RenderTarget& target) {
  painter_.draw(target, window_.getSize().x, window_.getSize().y, menuPicture(model_));
}

}  // namespace nineball::window
