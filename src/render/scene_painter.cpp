#include "render/scene_painter.hpp"

#include <SFML/Graphics/Sprite.hpp>
#include <SFML/Graphics/Text.hpp>
#include <cmath>

#include "render/guide_foul_painter.hpp"
#include "render/table_finish.hpp"

namespace nineball::render {

ScenePainter::ScenePainter(const TableGeometry& table, const Fonts& fonts)
    : table_(table),
      fonts_(fonts),
      view_(table.def, 1.0, 1.0),
      ball_painter_(fonts.bold),
      hud_painter_(fonts) {}

void ScenePainter::resize(double width_px, double height_px) {
  view_ = ViewTransform(table_.def, width_px, height_px);
  table_painter_.build(table_, view_);
  const auto w = static_cast<unsigned>(std::max(1.0, width_px));
  const auto h = static_cast<unsigned>(std::max(1.0, height_px));
  have_picture_ = table_picture_.create(w, h);
  if (have_picture_) {
    table_picture_.clear(toSf(kBackground));
    table_painter_.draw(table_picture_);
    table_picture_.display();
    // The materials are pixels over the flat shapes: worked out once per size, on the CPU.
    sf::Image picture = table_picture_.getTexture().copyToImage();
    finishTable(picture, view_, table_);
    sf::Texture finished;
    if (finished.loadFromImage(picture)) {
      table_picture_.draw(sf::Sprite(finished), sf::RenderStates(sf::BlendNone));
      table_picture_.display();
    }
  }
}

void ScenePainter::draw(sf::RenderTarget& target, const Frame& frame) {
  if (have_picture_) {
    target.draw(sf::Sprite(table_picture_.getTexture()), sf::RenderStates(sf::BlendNone));
  } else {
    target.clear(toSf(kBackground));
    table_painter_.draw(target);
  }
  // The guide goes under the balls: the balls hide its ends, the lines stay visible.
  if (frame.guide) {
    cue_painter_.drawGuide(target, view_, *frame.guide, frame.ball_radius, frame.guide_scale);
    if (!frame.guide_foul.empty()) {
      drawGuideFoul(target, view_, *frame.guide, frame.ball_radius, frame.guide_foul, fonts_);
    }
  }
  if (frame.bank) {
    cue_painter_.drawGuide(target, view_, *frame.bank, frame.ball_radius, frame.guide_scale, true);
  }
  ball_painter_.setLooks(frame.looks);
  hud_painter_.setLooks(frame.looks);
  ball_painter_.draw(target, view_, frame.balls, frame.ball_radius, frame.time, table_);
  if (frame.call) drawCall(target, view_, *frame.call, frame.ball_radius);
  if (frame.ghost) {
    const double r = view_.px(frame.ball_radius);
    const Vec2 c = view_.toPixels(frame.ghost->pos);
    ball_painter_.drawOne(target, frame.ghost->id, c, r, frame.ghost->legal ? 255 : 150);
    if (!frame.ghost->legal) {
      TriangleBatch cross;
      const double a = r * 0.75, w = std::max(2.0, r * 0.22);
      cross.line(c + Vec2{-a, -a}, c + Vec2{a, a}, w, sf::Color(220, 30, 30));
      cross.line(c + Vec2{-a, a}, c + Vec2{a, -a}, w, sf::Color(220, 30, 30));
      cross.draw(target);
      // The physics' reason, without its parenthesis of numbers.
      const std::string problem = frame.ghost->problem.substr(0, frame.ghost->problem.find(" ("));
      sf::Text why(problem, fonts_.regular, static_cast<unsigned>(std::max(10.0, r * 1.2)));
      why.setFillColor(sf::Color(255, 150, 130));
      const sf::FloatRect bounds = why.getLocalBounds();
      // Beside the ball, on whichever side has room.
      double x = c.x + r * 1.6;
      if (x + bounds.width + r > view_.widthPx()) x = c.x - r * 1.6 - bounds.width;
      why.setPosition(std::round(static_cast<float>(x)), std::round(static_cast<float>(c.y - r)));
      TriangleBatch box;
      box.roundedRect(x - r * 0.4, c.y - r * 1.1, bounds.width + r * 0.8,
                      bounds.top + bounds.height + r * 0.5, r * 0.4, sf::Color(10, 12, 14, 210));
      box.draw(target);
      target.draw(why);
    }
  }
  if (frame.cue) {
    std::optional<Vec2> cue = frame.cue->at;
    for (const BallState& b : frame.balls) {
      if (!cue && b.id == kCueBall && !b.pocket) cue = b.pos;
    }
    if (cue) {
      // Side spin moves the stick off the centre line, as the tip is.
      const Vec2 right = -perp(fromAngle(frame.cue->heading_rad));
      cue_painter_.drawStick(target, view_, *cue + right * (frame.cue->side * frame.ball_radius),
                             frame.cue->heading_rad, frame.ball_radius, frame.cue->pull);
    }
  }
  if (frame.cue && have_picture_) coverBands(target);
  hud_painter_.draw(target, view_, frame.hud);
}

void ScenePainter::coverBands(sf::RenderTarget& target) {
  // The stick passes under the HUD's bands: they are painted again over it, from the picture.
  const PixelRect top = view_.topBand(), bottom = view_.bottomBand();
  const int w = static_cast<int>(table_picture_.getSize().x);
  const int h = static_cast<int>(table_picture_.getSize().y);
  const int top_end = static_cast<int>(std::ceil(top.top + top.height));
  const int bottom_start = static_cast<int>(std::floor(bottom.top));
  for (const sf::IntRect rect :
       {sf::IntRect(0, 0, w, top_end), sf::IntRect(0, bottom_start, w, h - bottom_start)}) {
    if (rect.height <= 0) continue;
    sf::Sprite band(table_picture_.getTexture(), rect);
    band.setPosition(0.0f, static_cast<float>(rect.top));
    target.draw(band, sf::RenderStates(sf::BlendNone));
  }
}

}  // namespace nineball::render
