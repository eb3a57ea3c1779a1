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
      zoomed_(view_),
      ball_painter_(fonts.bold),
      hud_painter_(fonts) {}

void ScenePainter::setZoom(double zoom, Vec2 focus) {
  zoom_ = zoom;
  focus_ = focus;
  zoomed_ = view_.zoomed(zoom_, focus_);
}

void ScenePainter::resize(double width_px, double height_px) {
  view_ = ViewTransform(table_.def, width_px, height_px);
  zoomed_ = view_.zoomed(zoom_, focus_);
  table_painter_.build(table_, view_);
  const auto w = static_cast<unsigned>(std::max(1.0, width_px));
  const auto h = static_cast<unsigned>(std::max(1.0, height_px));
  have_picture_ = table_picture_.create(w, h);
  if (have_picture_) {
    table_picture_.setSmooth(true);  // zoomed, it is scaled up
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

bool sameTable(const TableGeometry& a, const TableGeometry& b) {
  const TableDef &x = a.def, &y = b.def;
  return x.length == y.length && x.width == y.width && x.corner_pocket == y.corner_pocket &&
         x.side_pocket == y.side_pocket && x.corner_jaw_deg == y.corner_jaw_deg &&
         x.side_jaw_deg == y.side_jaw_deg && x.corner_jaw_radius == y.corner_jaw_radius &&
         x.side_jaw_radius == y.side_jaw_radius && x.pockets == y.pockets && x.marks == y.marks &&
         a.pockets.size() == b.pockets.size() && a.cushion_loop == b.cushion_loop;
}

void ScenePainter::showTable(const TableGeometry& table) {
  if (sameTable(table_, table)) return;
  table_ = table;
  resize(view_.widthPx(), view_.heightPx());
}

void ScenePainter::drawTable(sf::RenderTarget& target) {
  if (!have_picture_) {
    target.clear(toSf(kBackground));
    table_painter_.draw(target);
    return;
  }
  sf::Sprite picture(table_picture_.getTexture());
  if (zoomed_.zoom() > 1.0) {
    // The picture made once per size, scaled round the focus: each of its pixels goes where
    // the zoomed view puts the point it shows.
    target.clear(toSf(kBackground));
    const Vec2 focus = view_.toPixels(zoomed_.focus());
    const Vec2 centre = view_.toPixels({0.0, 0.0});
    picture.setOrigin(static_cast<float>(focus.x), static_cast<float>(focus.y));
    picture.setPosition(static_cast<float>(centre.x), static_cast<float>(centre.y));
    picture.setScale(static_cast<float>(zoomed_.zoom()), static_cast<float>(zoomed_.zoom()));
    target.draw(picture);
    return;
  }
  target.draw(picture, sf::RenderStates(sf::BlendNone));
}

void ScenePainter::draw(sf::RenderTarget& target, const Frame& frame) {
  if (frame.table) showTable(*frame.table);
  drawTable(target);
  const ViewTransform& seen = zoomed_;  // the table's things, seen as zoomed
  // The guide goes under the balls: the balls hide its ends, the lines stay visible.
  if (frame.guide) {
    cue_painter_.drawGuide(target, seen, *frame.guide, frame.ball_radius, frame.guide_scale);
    if (!frame.guide_foul.empty()) {
      drawGuideFoulPath(target, seen, *frame.guide, frame.ball_radius);
    }
  }
  if (frame.bank) {
    cue_painter_.drawGuide(target, seen, *frame.bank, frame.ball_radius, frame.guide_scale, true);
  }
  if (frame.guide) cue_painter_.drawLandings(target, seen, *frame.guide, frame.ball_radius);
  ball_painter_.setLooks(frame.looks);
  hud_painter_.setLooks(frame.looks);
  ball_painter_.draw(target, seen, frame.balls, frame.ball_radius, frame.time, table_);
  if (frame.call) drawCall(target, seen, *frame.call, frame.ball_radius);
  // The foul warning is read, so it goes over the balls (a rack would hide it).
  if (frame.guide && !frame.guide_foul.empty()) {
    drawGuideFoulLabel(target, seen, *frame.guide, frame.ball_radius, frame.guide_foul, fonts_);
  }
  if (frame.ghost) {
    const double r = seen.px(frame.ball_radius);
    const Vec2 c = seen.toPixels(frame.ghost->pos);
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
      if (x + bounds.width + r > seen.widthPx()) x = c.x - r * 1.6 - bounds.width;
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
      cue_painter_.drawStick(target, seen, *cue + right * (frame.cue->side * frame.ball_radius),
                             frame.cue->heading_rad, frame.ball_radius, frame.cue->pull,
                             frame.cue->elevation_rad);
    }
  }
  if ((frame.cue || seen.zoom() > 1.0) && have_picture_) coverBands(target);
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
