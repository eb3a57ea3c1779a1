#pragma once

#include <SFML/Graphics/RenderTarget.hpp>

#include "play/aim_guide.hpp"
#include "render/triangle_batch.hpp"
#include "render/view_transform.hpp"

namespace nineball::render {

/// The cue stick behind the cue ball and the aim guide in front of it.
class CuePainter {
 public:
  /// The stick aimed along `heading_rad` at the cue ball (radius r), pulled back `pull` m and
  /// raised `elevation` rad: seen from above it shortens, and its shadow falls further from it
  /// the higher it is.
  void drawStick(sf::RenderTarget& target, const ViewTransform& view, Vec2 cue, double heading_rad,
                 double r, double pull, double elevation = 0.0);
  /// The path to the first ball or cushion, the ghost ball, the object ball's line and the
  /// cue ball's tangent line. `scale` lengthens or shortens the lines after the contact (the
  /// aim-guide setting); a `bank` guide (the path on from a cushion) is drawn fainter.
  void drawGuide(sf::RenderTarget& target, const ViewTransform& view, const AimGuide& guide,
                 double r, double scale = 1.0, bool bank = false);
  /// Where a jumping cue ball comes down (AimGuide::landings): a ring on the cloth at each, the
  /// first the brightest.
  void drawLandings(sf::RenderTarget& target, const ViewTransform& view, const AimGuide& guide,
                    double r);

 private:
  TriangleBatch batch_;
};

}  // namespace nineball::render
