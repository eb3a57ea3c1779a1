#pragma once

#include <algorithm>

#include "nineball/table.hpp"
#include "nineball/vec2.hpp"

namespace nineball::render {

/// A rectangle in pixels (y down).
struct PixelRect {
  double left = 0.0;
  double top = 0.0;
  double width = 0.0;
  double height = 0.0;

  bool contains(Vec2 p) const {
    return p.x >= left && p.x < left + width && p.y >= top && p.y < top + height;
  }
};

/// What the window shows, in metres: the table with its rails, a band above it for the
/// players and a band below for power and spin. Everything scales together.
struct SceneLayout {
  static constexpr double kRail = 0.14;  ///< cushion nose to the wood's outer edge, m
  static constexpr double kBand = 0.19;  ///< height of the HUD bands above and below, m
};

/// Metres to pixels for a window of a given size: the scene scaled to fit, proportions kept,
/// centred (letterboxed). World y points up, pixel y down. No SFML: the pixel test uses it.
class ViewTransform {
 public:
  ViewTransform(const TableDef& table, double width_px, double height_px)
      : table_(table), width_px_(width_px), height_px_(height_px) {
    const double w = table.length + 2.0 * SceneLayout::kRail;
    const double h = table.width + 2.0 * SceneLayout::kRail + 2.0 * SceneLayout::kBand;
    scale_ = std::max(1e-6, std::min(width_px / w, height_px / h));
    centre_ = {width_px / 2.0, height_px / 2.0};
  }

  /// The same window looking closer: `zoom` times as many pixels per metre (1 to 4), `focus`
  /// (m) at the table's centre on screen, held back so that the view stays on the table and
  /// its rails. The HUD keeps to hud(), the view unzoomed.
  ViewTransform zoomed(double zoom, Vec2 focus) const {
    ViewTransform v = hud();
    v.zoom_ = std::clamp(zoom, 1.0, 4.0);
    // The half-sizes seen round the focus, and how far the focus may go before the view
    // leaves the rails.
    const double half_w = table_.length / 2.0 + SceneLayout::kRail;
    const double half_h = table_.width / 2.0 + SceneLayout::kRail;
    const double reach_x = half_w - half_w / v.zoom_;
    const double reach_y = half_h - half_h / v.zoom_;
    v.focus_ = {std::clamp(focus.x, -reach_x, reach_x), std::clamp(focus.y, -reach_y, reach_y)};
    return v;
  }
  /// The view without zoom: where the HUD, its bands and dialogs are.
  ViewTransform hud() const {
    ViewTransform v = *this;
    v.zoom_ = 1.0;
    v.focus_ = {};
    return v;
  }
  double zoom() const { return zoom_; }
  /// The point (m) the zoomed view is centred on.
  Vec2 focus() const { return focus_; }

  /// Pixels per metre.
  double scale() const { return scale_ * zoom_; }
  double widthPx() const { return width_px_; }
  double heightPx() const { return height_px_; }
  const TableDef& table() const { return table_; }

  /// A point on the table (m, origin at its centre) in window pixels.
  Vec2 toPixels(Vec2 m) const {
    const double s = scale();
    return {centre_.x + (m.x - focus_.x) * s, centre_.y - (m.y - focus_.y) * s};
  }
  /// A window pixel as a point on the table (m).
  Vec2 toWorld(Vec2 px) const {
    const double s = scale();
    return {focus_.x + (px.x - centre_.x) / s, focus_.y + (centre_.y - px.y) / s};
  }
  /// A length in metres as pixels.
  double px(double metres) const { return metres * scale(); }

  /// The band above the table (players, ball on).
  PixelRect topBand() const { return band(+1.0); }
  /// The band below the table (power, message, spin).
  PixelRect bottomBand() const { return band(-1.0); }

 private:
  PixelRect band(double side) const {
    const double half_w = table_.length / 2.0 + SceneLayout::kRail;
    const double inner = table_.width / 2.0 + SceneLayout::kRail;
    const double outer = inner + SceneLayout::kBand;
    // The bands stay where they are however close the table is seen.
    const ViewTransform base = hud();
    const Vec2 a = base.toPixels({-half_w, side * outer});
    const Vec2 b = base.toPixels({half_w, side * inner});
    return {a.x, std::min(a.y, b.y), b.x - a.x, std::abs(b.y - a.y)};
  }

  TableDef table_;
  double width_px_;
  double height_px_;
  double scale_ = 1.0;
  Vec2 centre_;
  double zoom_ = 1.0;
  Vec2 focus_;
};

}  // namespace nineball::render
