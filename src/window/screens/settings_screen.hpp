#pragma once

#include <SFML/Window/Window.hpp>
#include <functional>

#include "render/menu_painter.hpp"
#include "window/menu.hpp"
#include "window/screens/screen.hpp"
#include "window/settings.hpp"

namespace nineball::window {

/// F2: the settings over the table, which goes on drawing (and its balls rolling) beneath; the
/// computer waits meanwhile. Each change is applied as it is made; closing saves them.
class SettingsScreen : public Screen {
 public:
  /// What the settings tell the window around them.
  struct Hooks {
    std::function<void(const Settings&)> changed;  ///< a setting changed (applied at once)
    std::function<void(const sf::Event&)> let_go;  ///< a key held in the game let go
    std::function<void()> screenshot;              ///< F12
    std::function<void()> closed;                  ///< the settings closed (saved then)
  };

  SettingsScreen(const Settings& settings, bool muted_by_option, const sf::Window& window,
                 render::MenuPainter& painter, Hooks hooks);

  void event(const sf::Event& event) override;
  void update(double, bool) override {}
  void draw(sf::RenderTarget& target) override;
  bool covers() const override { return false; }
  bool finished() const override { return model_.outcome() != MenuModel::Outcome::None; }
  void closed() override { hooks_.closed(); }

 private:
  MenuModel model_;
  const sf::Window& window_;
  render::MenuPainter& painter_;
  Hooks hooks_;
};

}  // namespace nineball::window
