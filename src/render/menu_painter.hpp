#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>
#include <string>
#include <vector>

#include "render/fonts.hpp"
#include "render/menu_layout.hpp"
#include "render/triangle_batch.hpp"

namespace nineball::render {

/// One row of the menu as the painter sees it.
struct MenuLine {
  std::string label;
  std::string value;    ///< drawn on the right: a choice's value, a field's text, a note
  bool choice = false;  ///< a value that Left / Right change: drawn between arrows
  bool field = false;   ///< a text field: drawn in a box
  bool enabled = true;
  bool editing = false;  ///< the field has the keyboard: a caret after its text
};

/// What the menu shows.
struct MenuPicture {
  std::string title;
  std::string subtitle;  ///< beside the title, dimmer
  std::vector<MenuLine> lines;
  int selected = 0;
  std::string hint;  ///< the keys, under the rows
};

/// Draws the start menu or the settings screen: a panel in the middle of the window, its rows
/// highlighted when selected, every text shrunk to fit its place (measured, not guessed).
class MenuPainter {
 public:
  explicit MenuPainter(const Fonts& fonts) : fonts_(fonts) {}

  /// Dims what is behind, then draws the panel for a window of `width` x `height` pixels.
  void draw(sf::RenderTarget& target, double width, double height, const MenuPicture& menu);

  /// Sets `text` to `size` px, smaller if needed so that it is at most `max_width` wide and
  /// `max_height` tall; returns its width.
  static double fit(sf::Text& text, double size, double max_width, double max_height);

 private:
  void put(sf::RenderTarget& target, sf::Text& text, double x, const PixelRect& box);

  const Fonts& fonts_;
  TriangleBatch batch_;
};

}  // namespace nineball::render
