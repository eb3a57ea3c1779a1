#include "window/screens/online_lobby_screen.hpp"

#include <string>

#include "render/hud_layout.hpp"

namespace nineball::window {

void OnlineLobbyScreen::event(const sf::Event& event) {
  if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::Escape) {
    cancel();
  } else if (event.type == sf::Event::MouseButtonPressed &&
             event.mouseButton.button == sf::Mouse::Left) {
    const OnlinePlay* online = hooks_.online();
    if (!online) return;
    const render::HudLayout layout =
        render::HudLayout::of(hooks_.view(), lobbyDialog(*online).dialog);
    const Vec2 px{static_cast<double>(event.mouseButton.x),
                  static_cast<double>(event.mouseButton.y)};
    if (layout.button_right.contains(px)) cancel();
  }
}

void OnlineLobbyScreen::draw(sf::RenderTarget& target) {
  if (const OnlinePlay* online = hooks_.online()) hooks_.draw(target, lobbyDialog(*online));
}

bool OnlineLobbyScreen::finished() const {
  const OnlinePlay* online = hooks_.online();
  return cancelled_ || !online || online->started();
}

void OnlineLobbyScreen::cancel() {
  if (cancelled_) return;
  cancelled_ = true;
  hooks_.cancel();
}

render::HudState lobbyDialog(const OnlinePlay& online) {
  render::HudState hud;
  hud.dialog = render::DialogLook::box();
  hud.dialog->width = 1.7;  // the join line whole, in the type of the other lines
  hud.dialog->height = 0.66;
  hud.button_right = "Cancel (Esc)";
  const bool host = online.side() == net::Side::Host;
  hud.overlay_title = host ? "Hosting an online game" : "Joining an online game";
  switch (online.stage()) {
    case OnlinePlay::Stage::Waiting:
      if (host) {
        hud.overlay_lines = {
            "Waiting for a friend to join on port " + std::to_string(online.port()) + ".",
            "Your join code: " + online.joinCode(),
            "Your friend types:", "    " + online.joinLine(),
            "or chooses Play online > Join in the menu, with this address and code."};
      } else {
        hud.overlay_lines = {online.banner()};
      }
      break;
    case OnlinePlay::Stage::Handshake:
    case OnlinePlay::Stage::Playing:
    case OnlinePlay::Stage::Lost:
      hud.overlay_lines = {"Connected: greeting the other side..."};
      break;
    case OnlinePlay::Stage::Over:
      hud.overlay_title = "No online game";
      hud.overlay_lines = {online.why()};
      hud.button_right = "Back (Esc)";
      break;
  }
  return hud;
}

}  // namespace nineball::window
