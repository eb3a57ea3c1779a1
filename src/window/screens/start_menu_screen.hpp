#pragma once

#include <functional>
#include <optional>

#include "window/menu.hpp"
#include "window/rack_save.hpp"
#include "window/screens/screen.hpp"
#include "window/start_menu.hpp"

namespace nineball::window {

/// The start menu over the table (drawn behind its panel): it covers the table, which neither
/// plays nor takes events meanwhile. Once the player picks, the session becomes the game chosen
/// (startChosenGame) and `done` is told what was chosen and whether a game started.
class StartMenuScreen : public Screen {
 public:
  using Done = std::function<void(MenuModel::Outcome outcome, bool started)>;
  /// A key held at the table when the menu opened (Esc) is let go there.
  using LetGo = std::function<void(const sf::Event&)>;

  StartMenuScreen(StartMenuContext ctx, GameSession& session, Seats& seats, Settings& settings,
                  const GameSession::TurnObserver& observer, Done done, LetGo let_go);

  void event(const sf::Event& event) override;
  void update(double, bool) override {}
  void draw(sf::RenderTarget& target) override;
  bool covers() const override { return true; }
  bool finished() const override { return model_.outcome() != MenuModel::Outcome::None; }
  void closed() override;

 private:
  StartMenuContext ctx_;
  GameSession& session_;
  Seats& seats_;
  Settings& settings_;
  const GameSession::TurnObserver& observer_;
  Done done_;
  LetGo let_go_;
  std::optional<SavedRack> saved_;  // the rack "Resume rack" picks up, as the menu opened
  MenuModel model_;
};

}  // namespace nineball::window
