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

  /// Pixels per metre.
  double scale() const { return scale_; }
  double widthPx() const { return width_px_; }
  double heightPx() const { return height_px_; }
  const TableDef& table() const { return table_; }

  /// A point on the table (m, origin at its centre) in window pixels.
  Vec2 toPixels(Vec2 m) const { return {centre_.x + m.x * scale_, centre_.y - m.y * scale_}; }
  /// A window pixel as a point on the table (m).
  Vec2 toWorld(Vec2 px) const { return {(px.x - centre_.x) / scale_, (centre_.y - px.y) / scale_}; }
  /// A length in metres as pixels.
  double px(double metres) const { return metres * scale_; }

  /// The band above the table (players, ball on).
  PixelRect topBand() const { return band(+1.0); }
  /// The band below the table (power, message, spin).
  PixelRect bottomBand() const { return band(-1.0); }

 private:
  PixelRect band(double side) const {
    const double half_w = table_.length / 2.0 + SceneLayout::kRail;
    const double inner = table_.width / 2.0 + SceneLayout::kRail;
    const double outer = inner + SceneLayout::kBand;
    const Vec2 a = toPixels({-half_w, side * outer});
    const Vec2 b = toPixels({half_w, side * inner});
    return {a.x, std::min(a.y, b.y), b.x - a.x, std::abs(b.y - a.y)};
  }

  TableDef table_;
  double width_px_;
  double height_px_;
  double scale_ = 1.0;
  Vec2 centre_;
};

}  // namespace nineball::render
