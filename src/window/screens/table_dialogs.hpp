#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Window/Event.hpp>
#include <functional>

#include "render/view_transform.hpp"
#include "window/game_input.hpp"
#include "window/game_session.hpp"
#include "window/screens/dialog_screen.hpp"
#include "window/seats/seats.hpp"
#include "window/ui_state.hpp"

namespace nineball::window {

/// The table as its dialogs see it: its state calls for them (dialogCalledFor), their buttons lie
/// where the HUD lays them out, their answers go to the session, the window's flags and
/// requests.
class TableDialogs : public DialogTable {
 public:
  /// What the window around the table lends: the view the pointer is read through, the table's
  /// own handling of an event, and the drawing of the dialog over the table's picture.
  struct Hooks {
    std::function<const render::ViewTransform&()> view;
    std::function<void(const sf::Event&)> pass_down;
    std::function<void(sf::RenderTarget&)> draw;
  };

  TableDialogs(GameSession& session, UiState& ui, const Seats& seats, WindowRequests& requests,
               Hooks hooks)
      : session_(session), ui_(ui), seats_(seats), requests_(requests), hooks_(std::move(hooks)) {}

  DialogKind dialogWanted() const override;
  bool othersDecide() const override { return seats_.controls(session_); }
  DialogButton buttonAt(Vec2 px) const override;
  void passDown(const sf::Event& event) override { hooks_.pass_down(event); }
  void drawDialog(sf::RenderTarget& target) override { hooks_.draw(target); }
  void closeHelp() override { ui_.help = false; }
  void closeQuestion() override { ui_.confirm_quit = false; }
  void leave() override;
  void decide(bool shoot_now, bool replace) override { session_.decide(shoot_now, replace); }
  void rematch() override { session_.rematch(); }
  void quit() override { requests_.quit = true; }

 private:
  GameSession& session_;
  UiState& ui_;
  const Seats& seats_;
  WindowRequests& requests_;
  Hooks hooks_;
};

}  // namespace nineball::window
