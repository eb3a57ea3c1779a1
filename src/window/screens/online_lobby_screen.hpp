#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Window/Event.hpp>
#include <functional>

#include "render/hud_state.hpp"
#include "render/view_transform.hpp"
#include "window/online_play.hpp"
#include "window/screens/screen.hpp"

namespace nineball::window {

/// The online game before it begins: the host waits for a friend (and shows the line the friend
/// types), the joiner connects. It lies over the table, whose frames keep the link going, and
/// leaves once the two sides have greeted each other; Esc or its Cancel button leaves the online
/// game. A link that ends before the game began stays on it, with the reason, until Esc.
class OnlineLobbyScreen : public Screen {
 public:
  /// What the table lends the lobby.
  struct Hooks {
    std::function<const OnlinePlay*()> online;  ///< the table's online game (nullptr once left)
    std::function<const render::ViewTransform&()> view;  ///< the view its button is read through
    std::function<void()> cancel;                        ///< the online game left
    std::function<void(sf::RenderTarget&, const render::HudState&)> draw;
  };

  explicit OnlineLobbyScreen(Hooks hooks) : hooks_(std::move(hooks)) {}

  void event(const sf::Event& event) override;
  void update(double, bool) override {}
  void draw(sf::RenderTarget& target) override;
  bool covers() const override { return false; }
  bool busy() const override { return true; }  // the link's clocks run while it waits
  bool finished() const override;

 private:
  void cancel();

  Hooks hooks_;
  bool cancelled_ = false;
};

/// What the lobby says of the online game now: the host's join line and code, the joiner's
/// connection, the handshake, or why the link ended; a Cancel (Back) button.
render::HudState lobbyDialog(const OnlinePlay& online);

}  // namespace nineball::window
