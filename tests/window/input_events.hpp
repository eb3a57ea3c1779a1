// Window events made by hand, and a game's window pieces as the loop holds them, for the tests
// that drive GameInput (and the dialogs over the table, as the window routes events) without a
// window.
#pragma once

#include <SFML/Window/Event.hpp>
#include <cmath>

#include "render/view_transform.hpp"
#include "window/game_input.hpp"
#include "window/game_session.hpp"
#include "window/screens/table_dialogs.hpp"
#include "window/seats/seats.hpp"
#include "window/ui_state.hpp"

namespace nineball::window {

inline sf::Event mouse(sf::Event::EventType type, Vec2 px) {
  sf::Event e{};
  e.type = type;
  if (type == sf::Event::MouseMoved) {
    e.mouseMove.x = static_cast<int>(std::lround(px.x));
    e.mouseMove.y = static_cast<int>(std::lround(px.y));
  } else {
    e.mouseButton.button = sf::Mouse::Left;
    e.mouseButton.x = static_cast<int>(std::lround(px.x));
    e.mouseButton.y = static_cast<int>(std::lround(px.y));
  }
  return e;
}

inline sf::Event key(sf::Keyboard::Key code, bool shift = false) {
  sf::Event e{};
  e.type = sf::Event::KeyPressed;
  e.key.code = code;
  e.key.shift = shift;
  return e;
}

inline sf::Event release(sf::Keyboard::Key code) {
  sf::Event e = key(code);
  e.type = sf::Event::KeyReleased;
  return e;
}

inline sf::Event wheel(float notches) {
  sf::Event e{};
  e.type = sf::Event::MouseWheelScrolled;
  e.mouseWheelScroll.wheel = sf::Mouse::VerticalWheel;
  e.mouseWheelScroll.delta = notches;
  return e;
}

/// A game's window pieces, as the loop holds them.
struct InputTable {
  explicit InputTable(const MatchSetup& setup = {}, bool practice = false) : s(setup, practice) {}
  GameSession s;
  UiState ui;
  Seats seats{1};
  GameInput input{s, ui, seats};
  render::ViewTransform view{s.match().world().table().def, 1280, 800};
  TableDialogs dialogs{
      s,
      ui,
      seats,
      input.requests(),
      {[this]() -> const render::ViewTransform& { return view; },
       [this](const sf::Event& e) { input.handle(e, view); }, [](sf::RenderTarget&) {}}};
  /// The event as the window routes it: to the dialog the table calls for, else to the input.
  void send(const sf::Event& e) {
    if (const auto dialog = makeDialog(dialogs.dialogWanted(), dialogs)) {
      dialog->event(e);
    } else {
      input.handle(e, view);
    }
  }
  void tap(sf::Keyboard::Key k, bool shift = false) {
    send(key(k, shift));
    send(release(k));
  }
  void mouseTo(Vec2 m) { input.handle(mouse(sf::Event::MouseMoved, view.toPixels(m)), view); }
  void pointerAt(Vec2 px) { input.handle(mouse(sf::Event::MouseMoved, px), view); }
  void click(Vec2 m, Vec2 release_at) {
    send(mouse(sf::Event::MouseButtonPressed, view.toPixels(m)));
    send(mouse(sf::Event::MouseMoved, view.toPixels(release_at)));
    send(mouse(sf::Event::MouseButtonReleased, view.toPixels(release_at)));
  }
};

}  // namespace nineball::window
