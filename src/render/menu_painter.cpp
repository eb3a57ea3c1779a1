#include "render/menu_painter.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::render {
namespace {

const sf::Color kShade(8, 10, 12, 170);
const sf::Color kPanel(16, 20, 24, 240);
const sf::Color kEdge(70, 120, 90);
const sf::Color kSelected(54, 92, 70);
const sf::Color kField(34, 40, 46);
const sf::Color kText(236, 236, 230);
const sf::Color kDim(150, 156, 160);
const sf::Color kGrey(96, 100, 104);
const sf::Color kAccent(255, 214, 90);

sf::Text makeText(const std::string& s, const sf::Font& font) {
  return sf::Text(sf::String::fromUtf8(s.begin(), s.end()), font);
}

double widthOf(const sf::Text& t) {
  const sf::FloatRect b = t.getLocalBounds();
  return b.left + b.width;
}

}  // namespace

double MenuPainter::fit(sf::Text& text, double size, double max_width, double max_height) {
  auto px = static_cast<unsigned>(std::max(1.0, std::floor(std::min(size, max_height))));
  text.setCharacterSize(px);
  double w = widthOf(text);
  // The first guess scales by the overflow; rounding and kerning may need a pixel or two more.
  if (w > max_width && w > 0.0) {
    px = static_cast<unsigned>(std::max(1.0, std::floor(px * max_width / w)));
    text.setCharacterSize(px);
    w = widthOf(text);
  }
  while (w > max_width && px > 1) {
    text.setCharacterSize(--px);
    w = widthOf(text);
  }
  return w;
}

// Draws `text` with its left edge at x, centred in the height of `box`.
void MenuPainter::put(sf::RenderTarget& target, sf::Text& text, double x, const PixelRect& box) {
  // Centre a capital and a descender of this font and size, not this text's own ink, so
  // that texts side by side share a baseline.
  const sf::Text probe("Hg", *text.getFont(), text.getCharacterSize());
  const sf::FloatRect b = probe.getLocalBounds();
  const double y = box.top + (box.height - b.height) / 2.0 - b.top;
  text.setPosition(std::round(static_cast<float>(x)), std::round(static_cast<float>(y)));
  target.draw(text);
}

void MenuPainter::draw(sf::RenderTarget& target, double width, double height,
                       const MenuPicture& menu) {
  const MenuLayout m = MenuLayout::of(width, height, static_cast<int>(menu.lines.size()));
  const double t = m.text_px;
  batch_.clear();
  batch_.roundedRect(0.0, 0.0, width, height, 0.0, kShade);
  const PixelRect& p = m.panel;
  batch_.roundedRect(p.left - 2.0, p.top - 2.0, p.width + 4.0, p.height + 4.0, t * 0.8 + 2.0,
                     kEdge);
  batch_.roundedRect(p.left, p.top, p.width, p.height, t * 0.8, kPanel);
  for (std::size_t i = 0; i < menu.lines.size(); ++i) {
    const PixelRect& r = m.rows[i];
    if (static_cast<int>(i) == menu.selected && menu.lines[i].enabled) {
      batch_.roundedRect(r.left, r.top, r.width, r.height, r.height / 4.0, kSelected);
    }
  }
  batch_.draw(target);

  // The title, and the subtitle right-aligned in what room is left.
  sf::Text title = makeText(menu.title, fonts_.bold);
  title.setFillColor(kAccent);
  const double title_w = fit(title, m.title_px, m.title.width, m.title.height);
  put(target, title, m.title.left, m.title);
  if (!menu.subtitle.empty()) {
    sf::Text sub = makeText(menu.subtitle, fonts_.regular);
    sub.setFillColor(kDim);
    const double room = m.title.width - title_w - t;
    if (room > t) {
      const double w = fit(sub, t * 0.8, room, m.title.height);
      put(target, sub, m.title.left + m.title.width - w, m.title);
    }
  }

  for (std::size_t i = 0; i < menu.lines.size(); ++i) {
    const MenuLine& line = menu.lines[i];
    const PixelRect& r = m.rows[i];
    const double inner = t * 0.6;
    const double room = r.width - 2.0 * inner;
    const sf::Color colour = line.enabled ? kText : kGrey;
    sf::Text label = makeText(line.label, fonts_.regular);
    label.setFillColor(colour);
    std::string shown = line.value;
    if (line.choice) shown = "\u25C0 " + shown + " \u25B6";
    if (line.editing) shown += "_";
    sf::Text value = makeText(shown, line.choice ? fonts_.bold : fonts_.regular);
    value.setFillColor(!line.enabled ? kGrey : line.editing ? kAccent : kText);
    // Label and value share the row. When they would meet, the value shrinks first (to
    // two thirds of the size), then the label gives up room too.
    const double size = t;
    const double gap = t;
    const double max_h = r.height * 0.8;
    double label_w = fit(label, size, room, max_h);
    if (!shown.empty()) {
      double value_w = fit(value, size, room, max_h);
      if (label_w + gap + value_w > room) {
        const double shrink = std::max(2.0 / 3.0, (room - label_w - gap) / value_w);
        value_w = fit(value, size * shrink, room, max_h);
      }
      if (label_w + gap + value_w > room) {
        label_w = fit(label, size, std::max(room * 0.3, room - gap - value_w), max_h);
      }
    }
    put(target, label, r.left + inner, r);
    if (!shown.empty()) {
      const double vw = fit(value, value.getCharacterSize(), room - label_w - gap, max_h);
      const double x = r.left + r.width - inner - vw;
      if (line.field) {
        TriangleBatch box;
        const double pad = t * 0.3;
        box.roundedRect(x - pad, r.top + r.height * 0.1, vw + 2.0 * pad, r.height * 0.8, pad,
                        line.editing ? sf::Color(70, 60, 20) : kField);
        box.draw(target);
      }
      put(target, value, x, r);
    }
  }

  if (!menu.hint.empty()) {
    sf::Text hint = makeText(menu.hint, fonts_.regular);
    hint.setFillColor(kDim);
    const double w = fit(hint, t * 0.75, m.hint.width, m.hint.height);
    put(target, hint, m.hint.left + (m.hint.width - w) / 2.0, m.hint);
  }
}

}  // namespace nineball::render
