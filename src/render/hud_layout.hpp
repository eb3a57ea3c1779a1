#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "render/hud_state.hpp"
#include "render/view_transform.hpp"

namespace nineball::render {

/// Where the HUD's parts sit in the window, so that the painter draws them and the input
/// finds them in the same place. No SFML.
struct HudLayout {
  PixelRect power_bar;  ///< the power gauge in the bottom band
  PixelRect message;    ///< the message lines between the gauge and the spin icon
  Vec2 spin_centre;     ///< the cue-ball icon that sets the tip (px)
  double spin_radius = 0.0;
  /// The cue seen from the side: a quarter ring round the icon's upper left, from level (on
  /// the left) to straight down (at the top), where a click tilts the cue.
  double tilt_inner = 0.0;
  double tilt_outer = 0.0;
  PixelRect panel;                 ///< a dialog over the table (help, push-out choice, game over)
  PixelRect button_left;           ///< the dialog's first button
  PixelRect button_right;          ///< the dialog's second button
  PixelRect button_middle;         ///< a third between them (three_buttons), else empty
  double text_px = 12.0;           ///< the HUD's character size
  double spin_labels_right = 0.0;  ///< the right edge of the spin icon's labels (px)

  /// No text is drawn larger than needed below this size; a line that does not fit its room
  /// shrinks instead, so small windows keep every line inside its place.
  static constexpr double kMinTextPx = 10.0;
  /// How far past the tilt ring the cue's marker on it reaches, in spin-icon radii.
  static constexpr double kTiltMarkReach = 0.25;
  /// The room (m at the view's scale) left of the spin icon for its three labels.
  static constexpr double kSpinLabelsWidth = 0.42;

  /// How far (m) from a ball's centre a strip must stay to leave the ball in sight: its radius
  /// and a little.
  static constexpr double kKeepClearReach = 0.03;

  /// The layout for a view (its size and scale) and the dialog shown. A strip (the push-out
  /// choice, the rack's end) lies across the table and leaves the balls in sight: along a long
  /// cushion when that hides none of `keep_clear` (the balls, m), else the place across the
  /// table (or, failing that, over a HUD band) that hides the fewest.
  static HudLayout of(const ViewTransform& zoomed_view,
                      const std::optional<DialogLook>& dialog = std::nullopt,
                      const std::vector<Vec2>& keep_clear = {}, bool three_buttons = false) {
    // The HUD does not zoom with the table.
    const ViewTransform view = zoomed_view.hud();
    const DialogLook look = dialog.value_or(DialogLook{});
    HudLayout h;
    const double s = view.scale();
    const PixelRect band = view.bottomBand();
    const double margin = 0.03 * s;
    h.text_px = std::max(kMinTextPx, 0.048 * s);
    h.power_bar = {band.left + margin, band.top + band.height * 0.36, 0.5 * s, 0.04 * s};
    h.spin_radius = 0.07 * s;
    h.spin_centre = {band.left + band.width - margin - h.spin_radius, band.top + band.height / 2.0};
    const double msg_left = h.power_bar.left + h.power_bar.width + 2.0 * margin;
    h.tilt_inner = 1.12 * h.spin_radius;
    h.tilt_outer = 1.42 * h.spin_radius;
    // Clear of the cue's marker on the ring, which reaches past it by a quarter of the icon.
    h.spin_labels_right =
        h.spin_centre.x - h.tilt_outer - kTiltMarkReach * h.spin_radius - 0.02 * s;
    const double msg_right = h.spin_labels_right - std::max(kSpinLabelsWidth * s, 0.2 * band.width);
    // A narrow window's letterbox below the table gives a long message its second line.
    const double below = view.heightPx() - band.top - 0.01 * s;
    h.message = {msg_left, band.top + 0.01 * s, msg_right - msg_left,
                 std::clamp(below, band.height - 0.02 * s, 2.0 * band.height)};
    const Vec2 c = view.toPixels({0.0, 0.0});
    const double pw = look.width * s;
    const double ph = look.height * s;
    h.panel = {c.x - pw / 2.0, c.y - ph / 2.0, pw, ph};
    if (look.strip) h.panel.top = stripTop(view, h.panel, keep_clear);
    const double bh = 0.085 * s, gap = 0.08 * s;
    const double by = h.panel.top + ph - bh - 0.04 * s;
    if (three_buttons) {
      // Narrower, so that three fit the strip's width with room at its ends.
      const double bw = 0.38 * s;
      h.button_middle = {c.x - bw / 2.0, by, bw, bh};
      h.button_left = {c.x - bw / 2.0 - gap / 2.0 - bw, by, bw, bh};
      h.button_right = {c.x + bw / 2.0 + gap / 2.0, by, bw, bh};
    } else {
      const double bw = 0.5 * s;
      h.button_left = {c.x - gap / 2.0 - bw, by, bw, bh};
      h.button_right = {c.x + gap / 2.0, by, bw, bh};
    }
    return h;
  }

  /// How many of `points` (m) a panel hides.
  static int hiddenBy(const ViewTransform& view, const PixelRect& panel,
                      const std::vector<Vec2>& points) {
    const double reach = view.px(kKeepClearReach);
    int n = 0;
    for (const Vec2& p : points) {
      const Vec2 c = view.toPixels(p);
      if (c.x + reach > panel.left && c.x - reach < panel.left + panel.width &&
          c.y + reach > panel.top && c.y - reach < panel.top + panel.height) {
        ++n;
      }
    }
    return n;
  }

  /// The top of a strip that hides none of `keep` if it can: the places along the long
  /// cushions first, then across the table from both sides, then over the HUD's bands.
  static double stripTop(const ViewTransform& view, PixelRect panel,
                         const std::vector<Vec2>& keep) {
    const double edge = view.table().width / 2.0 - 0.04;
    const double upper = view.toPixels({0.0, edge}).y;
    const double lower = view.toPixels({0.0, -edge}).y - panel.height;
    std::vector<double> tops;
    constexpr int kSteps = 24;
    for (int i = 0; i <= kSteps / 2; ++i) {
      tops.push_back(upper + (lower - upper) * i / kSteps);
      tops.push_back(lower - (lower - upper) * i / kSteps);
    }
    const PixelRect below = view.bottomBand();
    tops.push_back(view.topBand().top);
    tops.push_back(below.top + below.height - panel.height);
    double best = tops.front();
    int best_hidden = -1;
    for (double top : tops) {
      panel.top = top;
      const int hidden = hiddenBy(view, panel, keep);
      if (best_hidden < 0 || hidden < best_hidden) {
        best = top;
        best_hidden = hidden;
      }
      if (hidden == 0) break;
    }
    return best;
  }

  /// Where on the tilt ring a cue `elevation` (rad) above the table points from, as a unit
  /// vector from the icon's centre (window axes, y down).
  static Vec2 tiltDirection(double elevation) {
    return {-std::cos(elevation), -std::sin(elevation)};
  }

  /// The elevation (rad, 0 to pi/2) a press at `px` asks for, or nothing when it is off the
  /// tilt ring (with a little slack round it).
  std::optional<double> tiltAt(Vec2 px) const {
    const Vec2 d = px - spin_centre;
    const double r = length(d);
    if (r < tilt_inner - 0.05 * spin_radius || r > tilt_outer + 0.15 * spin_radius) return {};
    if (d.x > 0.1 * spin_radius || d.y > 0.1 * spin_radius) return {};
    return tiltToward(px);
  }

  /// The elevation (rad, 0 to pi/2) of the ring's point in the direction of `px`: a drag past
  /// either end of the ring holds the cue at that end.
  double tiltToward(Vec2 px) const {
    const Vec2 d = px - spin_centre;
    return std::atan2(std::max(-d.y, 0.0), std::max(-d.x, 1e-9));
  }
};

}  // namespace nineball::render
