#include "render/cue_painter.hpp"

#include <algorithm>
#include <cmath>

#include "render/cue_stick_shape.hpp"

namespace nineball::render {
namespace {

struct Section {
  double to;  // m from the tip where this section ends
  Rgb colour;
};

// Tip leather (chalked blue), ferrule, maple shaft, joint, dark butt with a wrap, bumper.
constexpr Section kSections[] = {
    {0.010, {58, 104, 190}}, {0.035, {242, 238, 226}}, {0.760, {226, 196, 142}},
    {0.775, {40, 40, 44}},   {1.050, {118, 58, 30}},   {1.300, {30, 30, 34}},
    {1.450, {118, 58, 30}},  {1.470, {18, 18, 18}},
};

constexpr double kGuideLength = 0.45;  // m of the object ball's line on a full hit

// A ball's shadow falls (0.006, 0.009) m from it, down and right, with its centre at height R:
// a thing at height h casts its shadow h / R times as far.
Vec2 shadowOffset(const ViewTransform& view, double height, double r) {
  const double k = height / r;
  return {view.px(0.006 * k), view.px(0.009 * k)};
}

}  // namespace

void CuePainter::drawStick(sf::RenderTarget& target, const ViewTransform& view, Vec2 cue,
                           double heading_rad, double r, double pull, double elevation) {
  batch_.clear();
  const Vec2 dir = fromAngle(heading_rad);
  const Vec2 n = perp(dir);
  const Vec2 tip = CueStickShape::tip(cue, dir, r, pull, elevation);
  const double seen = std::cos(elevation);  // the stick's length as seen from above, per metre
  auto half = [](double s) {
    return (CueStickShape::kTipWidth +
            (CueStickShape::kButtWidth - CueStickShape::kTipWidth) * s / CueStickShape::kLength) /
           2.0;
  };
  auto corner = [&](double s, double side) {
    return view.toPixels(tip - dir * (s * seen) + n * (side * half(s)));
  };
  // Shadow first, offset down and right as the balls' are, by the height of each end: the tip
  // meets the ball at its centre's height, the butt is higher by the stick's length times
  // sin(elevation).
  const auto outline = CueStickShape::outline(cue, dir, r, pull, elevation);
  const double tip_height = r + (r + CueStickShape::kRestGap + pull) * std::sin(elevation);
  const double butt_height = tip_height + CueStickShape::kLength * std::sin(elevation);
  const Vec2 tip_shadow = shadowOffset(view, tip_height, r);
  const Vec2 butt_shadow = shadowOffset(view, butt_height, r);
  batch_.quad(view.toPixels(outline[0]) + tip_shadow, view.toPixels(outline[1]) + tip_shadow,
              view.toPixels(outline[2]) + butt_shadow, view.toPixels(outline[3]) + butt_shadow,
              sf::Color(0, 0, 0, elevation > 0.0 ? 45 : 70));
  double from = 0.0;
  for (const Section& s : kSections) {
    batch_.quad(corner(from, 1.0), corner(from, -1.0), corner(s.to, -1.0), corner(s.to, 1.0),
                toSf(s.colour));
    from = s.to;
  }
  // A light streak along the shaft makes it round.
  batch_.line(view.toPixels(tip - dir * (0.04 * seen) + n * (half(0.04) * 0.4)),
              view.toPixels(tip - dir * (0.75 * seen) + n * (half(0.75) * 0.4)),
              std::max(1.0, view.px(0.003)), sf::Color(255, 250, 235, 90));
  batch_.draw(target);
}

void CuePainter::drawLandings(sf::RenderTarget& target, const ViewTransform& view,
                              const AimGuide& guide, double r) {
  batch_.clear();
  const double w = std::max(1.5, view.px(0.004));
  std::uint8_t alpha = 220;
  for (Vec2 at : guide.landings) {
    const Vec2 c = view.toPixels(at);
    batch_.softRing(c, view.px(0.7 * r) - w, view.px(0.7 * r), sf::Color(150, 220, 255, alpha));
    batch_.softRing(c, 0.0, std::max(1.5, view.px(0.12 * r)), sf::Color(150, 220, 255, alpha));
    alpha = static_cast<std::uint8_t>(alpha * 0.6);
  }
  batch_.draw(target);
}

void CuePainter::drawGuide(sf::RenderTarget& target, const ViewTransform& view,
                           const AimGuide& guide, double r, double scale, bool bank) {
  batch_.clear();
  const double w = std::max(1.5, view.px(0.004));
  const sf::Color path = bank ? sf::Color(190, 230, 255, 110) : sf::Color(255, 255, 255, 150);
  const double guide_length = kGuideLength * scale;
  batch_.softLine(view.toPixels(guide.start), view.toPixels(guide.end), w, path);
  const Vec2 end = view.toPixels(guide.end);
  // Scale 0: the cue ball's line alone, to the ghost ball, and nothing after the contact.
  const bool after_contact = scale > 0.0;
  if (!after_contact) {
    batch_.softRing(end, view.px(r) - w, view.px(r), sf::Color(255, 255, 255, 150));
    batch_.draw(target);
    return;
  }
  switch (guide.target) {
    case AimTarget::Ball: {
      batch_.softRing(end, view.px(r) - w, view.px(r), sf::Color(255, 255, 255, 190));
      const Vec2 dir = normalized(guide.end - guide.start);
      // A stun hit shares the speed: cos of the cut to the object ball, sin to the cue ball.
      const double along = std::clamp(dot(dir, guide.object_dir), 0.0, 1.0);
      const Vec2 object_centre = guide.end + guide.object_dir * (2.0 * r);
      const double object_len =
          std::min(r + guide_length * along, length(guide.object_end - object_centre));
      batch_.softLine(view.toPixels(object_centre),
                      view.toPixels(object_centre + guide.object_dir * object_len), w,
                      sf::Color(255, 226, 90, 220));
      const double across = std::sqrt(std::max(0.0, 1.0 - along * along));
      if (length(guide.cue_dir) > 0.0) {
        const double cue_len = std::min(guide_length * across, length(guide.cue_end - guide.end));
        batch_.softLine(end, view.toPixels(guide.end + guide.cue_dir * cue_len), w,
                        sf::Color(150, 210, 255, 200));
      }
      break;
    }
    case AimTarget::Cushion: {
      batch_.softRing(end, view.px(r) - w, view.px(r), sf::Color(255, 255, 255, 110));
      const Vec2 dir = normalized(guide.end - guide.start);
      const Vec2 n = guide.cushion_normal;
      const Vec2 bounce = dir - n * (2.0 * dot(dir, n));
      batch_.softLine(end, view.toPixels(guide.end + bounce * 0.2), w,
                      sf::Color(255, 255, 255, 70));
      break;
    }
    case AimTarget::Pocket:
      batch_.softRing(end, view.px(r) - w, view.px(r), sf::Color(255, 120, 100, 200));
      break;
  }
  batch_.draw(target);
}

}  // namespace nineball::render
