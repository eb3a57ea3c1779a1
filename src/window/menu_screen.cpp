#include "window/menu_screen.hpp"

#include <algorithm>
#include <iterator>
#include <optional>
#include <utility>

namespace nineball::window {
namespace {

std::optional<MenuKey> menuKey(sf::Keyboard::Key k) {
  switch (k) {
    case sf::Keyboard::Up:
      return MenuKey::Up;
    case sf::Keyboard::Down:
      return MenuKey::Down;
    case sf::Keyboard::Left:
      return MenuKey::Left;
    case sf::Keyboard::Right:
      return MenuKey::Right;
    case sf::Keyboard::Enter:
    case sf::Keyboard::Space:
      return MenuKey::Enter;
    case sf::Keyboard::Escape:
      return MenuKey::Escape;
    case sf::Keyboard::Backspace:
      return MenuKey::Backspace;
    case sf::Keyboard::Tab:
      return MenuKey::Tab;
    default:
      return std::nullopt;
  }
}

}  // namespace

std::optional<std::vector<MenuKey>> parseMenuKeys(const std::string& text, std::string& why) {
  static const std::pair<const char*, MenuKey> kNames[] = {
      {"up", MenuKey::Up},       {"down", MenuKey::Down},          {"left", MenuKey::Left},
      {"right", MenuKey::Right}, {"enter", MenuKey::Enter},        {"escape", MenuKey::Escape},
      {"tab", MenuKey::Tab},     {"backspace", MenuKey::Backspace}};
  std::vector<MenuKey> keys;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string word = text.substr(at, comma - at);
    at = comma + 1;
    if (word.empty()) continue;
    const auto* found = std::find_if(std::begin(kNames), std::end(kNames),
                                     [&](const auto& n) { return word == n.first; });
    if (found == std::end(kNames)) {
      why = "\"" + word.substr(0, 40) + "\" is not a menu key (up, down, left, right, enter, " +
            "escape, tab, backspace)";
      return std::nullopt;
    }
    keys.push_back(found->second);
  }
  return keys;
}

render::MenuPicture menuPicture(const MenuModel& model) {
  render::MenuPicture p;
  p.title = model.title();
  const bool main = model.screen() == MenuModel::Screen::Main;
  p.subtitle = main ? "pool on a real table" : "saved for the next game";
  for (const MenuRow& r : model.rows()) {
    render::MenuLine line;
    line.label = r.label;
    line.value = r.value;
    line.choice = r.kind == MenuRow::Kind::Choice && r.enabled;
    line.field = r.kind == MenuRow::Kind::Text && r.enabled;
    line.enabled = r.enabled;
    line.editing = r.editing;
    p.lines.push_back(line);
  }
  p.selected = model.selected();
  if (model.editing()) {
    p.hint = "Type the name    Backspace: erase    Enter: done";
  } else {
    p.hint = std::string("Up / Down: choose    Left / Right: change    Enter: select    Esc: ") +
             (main ? "quit" : "back");
  }
  return p;
}

bool handleMenuEvent(MenuModel& model, const sf::Event& event, double width, double height) {
  const int rows = static_cast<int>(model.rows().size());
  switch (event.type) {
    case sf::Event::KeyPressed: {
      // Space types a space in a name; everywhere else it selects.
      if (model.editing() && event.key.code == sf::Keyboard::Space) return false;
      if (const auto k = menuKey(event.key.code)) {
        model.key(*k);
        return true;
      }
      return false;
    }
    case sf::Event::TextEntered:
      if (!model.editing()) return false;
      model.text(event.text.unicode);
      return true;
    case sf::Event::MouseMoved: {
      const render::MenuLayout m = render::MenuLayout::of(width, height, rows);
      const int before = model.selected();
      model.hover(m.rowAt(
          {static_cast<double>(event.mouseMove.x), static_cast<double>(event.mouseMove.y)}));
      return model.selected() != before;
    }
    case sf::Event::MouseButtonPressed: {
      if (event.mouseButton.button != sf::Mouse::Left) return false;
      const render::MenuLayout m = render::MenuLayout::of(width, height, rows);
      model.click(m.rowAt(
          {static_cast<double>(event.mouseButton.x), static_cast<double>(event.mouseButton.y)}));
      return true;
    }
    default:
      return false;
  }
}

}  // namespace nineball::window
