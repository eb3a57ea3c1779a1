#pragma once

#include <array>
#include <cmath>

#include "nineball/vec2.hpp"

namespace nineball::render {

/// The cue stick to scale: a 1.47 m taper from a 13 mm tip to a 29 mm butt.
struct CueStickShape {
  static constexpr double kLength = 1.47;
  static constexpr double kTipWidth = 0.013;
  static constexpr double kButtWidth = 0.029;
  /// Gap between the tip and the cue ball when not pulled back, m.
  static constexpr double kRestGap = 0.008;
  /// How far a full drag pulls the stick back, m.
  static constexpr double kMaxPull = 0.3;

  /// Where the tip sits, seen from above, for a cue ball at `cue` (radius r) aimed along the
  /// unit `dir`, pulled back by `pull` metres along a cue raised `elevation` rad: a raised cue
  /// is foreshortened by cos(elevation).
  static Vec2 tip(Vec2 cue, Vec2 dir, double r, double pull, double elevation = 0.0) {
    return cue - dir * ((r + kRestGap + pull) * std::cos(elevation));
  }

  /// The outline in metres, seen from above: tip left, tip right, butt right, butt left. No
  /// SFML: the pixel test uses it to skip what the stick covers.
  static std::array<Vec2, 4> outline(Vec2 cue, Vec2 dir, double r, double pull,
                                     double elevation = 0.0) {
    const Vec2 t = tip(cue, dir, r, pull, elevation);
    const Vec2 b = t - dir * (kLength * std::cos(elevation));
    const Vec2 n = perp(dir);
    return {t + n * (kTipWidth / 2.0), t - n * (kTipWidth / 2.0), b - n * (kButtWidth / 2.0),
            b + n * (kButtWidth / 2.0)};
  }
};

}  // namespace nineball::render
