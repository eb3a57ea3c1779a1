#include "window/shot_png.hpp"

#include <SFML/Graphics/Image.hpp>
#include <SFML/Graphics/RenderTexture.hpp>
#include <SFML/Graphics/Text.hpp>
#include <algorithm>
#include <cmath>

#include "common/atomic_file.hpp"
#include "render/ball_painter.hpp"
#include "render/fonts.hpp"
#include "render/palette.hpp"
#include "render/png_capture.hpp"
#include "render/table_painter.hpp"
#include "render/triangle_batch.hpp"
#include "render/view_transform.hpp"
#include "window/display_probe.hpp"

namespace nineball::window {
namespace {

constexpr unsigned kWidth = 1600;
constexpr unsigned kHeight = 1000;
constexpr double kDash = 0.02;  // m: a sliding path's dashes and gaps
const sf::Color kContact(255, 255, 255);
const sf::Color kCushion(255, 214, 90);
const sf::Color kPocketed(255, 90, 70);

sf::Color pathColour(int id) {
  const auto c = render::ballColour(id);
  // The 6's green on the green cloth and the 8's black are lifted so that the paths show.
  sf::Color s(c.r, c.g, c.b);
  if (id == 6) s = sf::Color(90, 220, 120);
  if (id == 8) s = sf::Color(40, 40, 40);
  return s;
}

// Where ball `id` was at `t` (samples include every event's instant).
std::optional<Vec2> positionAt(const Trace& trace, int id, double t) {
  for (const BallTrace& b : trace.balls) {
    if (b.id != id || b.t.empty()) continue;
    const auto it = std::lower_bound(b.t.begin(), b.t.end(), t);
    const std::size_t i = std::min<std::size_t>(it - b.t.begin(), b.t.size() - 1);
    return Vec2{b.x[i], b.y[i]};
  }
  return std::nullopt;
}

void drawPaths(render::TriangleBatch& batch, const render::ViewTransform& view,
               const Trace& trace) {
  for (const BallTrace& b : trace.balls) {
    double along = 0.0;
    for (std::size_t i = 1; i < b.size(); ++i) {
      const Vec2 p{b.x[i - 1], b.y[i - 1]}, q{b.x[i], b.y[i]};
      const double len = length(q - p);
      if (len <= 0.0) continue;
      // The motion between two samples is the phase just after the first of them.
      const bool sliding = b.phase[i - 1] == TracePhase::Sliding;
      const bool gap = sliding && static_cast<long>(std::floor(along / kDash)) % 2 == 1;
      along += len;
      if (gap) continue;
      batch.line(view.toPixels(p), view.toPixels(q), 2.5, pathColour(b.id));
    }
  }
}

void drawEvents(render::TriangleBatch& batch, const render::ViewTransform& view, const SimResult& r,
                double ball_px) {
  for (const Event& e : r.events) {
    const auto at = positionAt(*r.trace, e.a, e.t);
    if (!at) continue;
    const Vec2 c = view.toPixels(*at);
    switch (e.type) {
      case EventType::BallBall: {
        // The contact point, between the two centres.
        const auto other = positionAt(*r.trace, e.b, e.t);
        const Vec2 m = other ? (c + view.toPixels(*other)) * 0.5 : c;
        batch.ring(m, 4.0, 6.5, kContact);
        break;
      }
      case EventType::Cushion: {
        const double s = 5.0;
        batch.line(c + Vec2{-s, 0}, c + Vec2{0, -s}, 2.0, kCushion);
        batch.line(c + Vec2{0, -s}, c + Vec2{s, 0}, 2.0, kCushion);
        batch.line(c + Vec2{s, 0}, c + Vec2{0, s}, 2.0, kCushion);
        batch.line(c + Vec2{0, s}, c + Vec2{-s, 0}, 2.0, kCushion);
        break;
      }
      case EventType::Pocket:
        batch.ring(c, ball_px * 1.05, ball_px * 1.05 + 3.0, kPocketed);
        break;
      case EventType::Miscue:
      case EventType::AllAtRest:
      case EventType::Airborne:
      case EventType::Land:
      case EventType::OffTable:
        break;
    }
  }
}

}  // namespace

bool writeShotPng(const Scene& scene, const SimResult& traced, const std::string& path,
                  std::string& why) {
  if (!traced.trace) {
    why = "the shot was not traced";
    return false;
  }
  const DisplayConnection display;
  if (!display.connected()) {
    why = "no display found; draw under a virtual display, e.g. xvfb-run -a nineball sim ...";
    return false;
  }
  const auto fonts = render::loadFonts(why);
  if (!fonts) return false;
  sf::RenderTexture picture;
  if (!picture.create(kWidth, kHeight)) {
    why = "cannot create an offscreen picture of " + std::to_string(kWidth) + "x" +
          std::to_string(kHeight);
    return false;
  }
  const TableGeometry table = buildTable(scene.table, scene.physics.ball_radius);
  const render::ViewTransform view(scene.table, kWidth, kHeight);
  picture.clear(render::toSf(render::kBackground));
  render::TablePainter table_painter;
  table_painter.build(table, view);
  table_painter.draw(picture);

  const double r_px = view.px(scene.physics.ball_radius);
  render::BallPainter balls(fonts->bold);
  for (const BallState& b : scene.balls) {
    if (!b.pocket) balls.drawOne(picture, b.id, view.toPixels(b.pos), r_px, 90);  // the start
  }
  render::TriangleBatch marks;
  drawPaths(marks, view, *traced.trace);
  drawEvents(marks, view, traced, r_px);
  marks.draw(picture);
  for (const BallState& b : traced.balls) {
    if (!b.pocket) balls.drawOne(picture, b.id, view.toPixels(b.pos), r_px);  // the end
  }
  const render::PixelRect band = view.bottomBand();
  sf::Text legend(
      "paths: sliding dashed, rolling solid    white ring: ball contact    yellow diamond: "
      "cushion    red ring: pocketed    faded: where each ball started",
      fonts->regular, static_cast<unsigned>(std::max(12.0, band.height * 0.22)));
  legend.setFillColor(sf::Color(210, 210, 205));
  const double fit = band.width / std::max(1.0f, legend.getLocalBounds().width);
  if (fit < 1.0) legend.setScale(static_cast<float>(fit), static_cast<float>(fit));
  legend.setPosition(static_cast<float>(band.left),
                     static_cast<float>(band.top + band.height * 0.3));
  picture.draw(legend);
  picture.display();
  return render::saveImage(picture.getTexture().copyToImage(), path, why);
}

}  // namespace nineball::window
