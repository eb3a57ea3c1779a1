#include "window/screens/start_menu_screen.hpp"

#include "window/menu_screen.hpp"

namespace nineball::window {

StartMenuScreen::StartMenuScreen(StartMenuContext ctx, GameSession& session, Seats& seats,
                                 Settings& settings, const GameSession::TurnObserver& observer,
                                 Done done, LetGo let_go)
    : ctx_(std::move(ctx)),
      session_(session),
      seats_(seats),
      settings_(settings),
      observer_(observer),
      done_(std::move(done)),
      let_go_(std::move(let_go)),
      saved_(loadRack(rackSavePath())),
      model_(openStartMenu(ctx_, settings_, saved_)) {}

void StartMenuScreen::event(const sf::Event& event) {
  // Else the table would take the key that opened the menu for still held, and ignore its next
  // press.
  if (event.type == sf::Event::KeyReleased || event.type == sf::Event::LostFocus) {
    let_go_(event);
  }
  handleMenuEvent(model_, event, ctx_.window.getSize().x, ctx_.window.getSize().y);
}

void StartMenuScreen::draw(sf::RenderTarget& target) {
  drawStartMenuOver(ctx_, target, model_);
}

void StartMenuScreen::closed() {
  // Closed with no choice (the window closed under it): the settings are kept, as on Quit.
  if (model_.outcome() == MenuModel::Outcome::None) model_.key(MenuKey::Escape);
  const bool started =
      startChosenGame(ctx_, model_, saved_, session_, seats_, settings_, observer_);
  done_(model_.outcome(), started);
}

}  // namespace nineball::window
