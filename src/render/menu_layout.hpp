#pragma once

#include <algorithm>
#include <vector>

#include "render/view_transform.hpp"

namespace nineball::render {

/// Where the menu's panel, title and rows sit in a window of a given size, so that the
/// painter draws them and the pointer finds them in the same place. Everything scales with
/// the window (640x480 to 3840x2160 and beyond) and the panel always fits inside it. No SFML.
struct MenuLayout {
  PixelRect panel;
  PixelRect title;
  std::vector<PixelRect> rows;
  PixelRect hint;         ///< the keys' line under the rows
  double text_px = 16.0;  ///< the rows' character size
  double title_px = 28.0;
  double pad = 16.0;  ///< the panel's inner margin

  static MenuLayout of(double width, double height, int row_count) {
    MenuLayout m;
    // 22 px rows at 1280x800, in proportion elsewhere.
    const double unit = std::min(width / 1280.0, height / 800.0);
    m.text_px = std::max(10.0, 22.0 * unit);
    const auto heightFor = [&](double t) { return t * (1.4 + 2.8 + 2.0 * row_count + 2.2 + 1.0); };
    // Too many rows for the window: everything smaller until the panel fits.
    const double room = 0.94 * height;
    if (heightFor(m.text_px) > room) m.text_px = std::max(6.0, room / heightFor(1.0));
    const double t = m.text_px;
    m.title_px = 1.6 * t;
    m.pad = 1.4 * t;
    const double w = std::min(0.94 * width, 34.0 * t);
    const double h = heightFor(t);
    m.panel = {(width - w) / 2.0, (height - h) / 2.0, w, h};
    const double inner_left = m.panel.left + m.pad;
    const double inner_width = w - 2.0 * m.pad;
    double y = m.panel.top + m.pad;
    m.title = {inner_left, y, inner_width, 2.4 * t};
    y += 2.8 * t;
    for (int i = 0; i < row_count; ++i) {
      m.rows.push_back({inner_left, y, inner_width, 1.8 * t});
      y += 2.0 * t;
    }
    y += 0.4 * t;
    m.hint = {inner_left, y, inner_width, 1.4 * t};
    return m;
  }

  /// The row under the pointer, or -1.
  int rowAt(Vec2 px) const {
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (rows[i].contains(px)) return static_cast<int>(i);
    }
    return -1;
  }
};

}  // namespace nineball::render
