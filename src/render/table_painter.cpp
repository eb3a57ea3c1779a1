#include "render/table_painter.hpp"

#include <cmath>

#include "nineball/table_markings.hpp"

namespace nineball::render {
namespace {

// The cushion rubber's depth from nose to rail (the jaws are built about as deep).
constexpr double kCushionDepth = 0.05;
constexpr double kWoodEdge = 0.012;
constexpr Rgb kWoodDark{66, 36, 18};
constexpr Rgb kPocketRimColour{48, 44, 40};
constexpr double kPocketRim = 0.007;  // m
constexpr Rgb kClothShade{34, 112, 68};
constexpr Rgb kMarking{236, 244, 236};

std::vector<Vec2> toPixels(const ViewTransform& view, const std::vector<Vec2>& metres) {
  std::vector<Vec2> px;
  px.reserve(metres.size());
  for (Vec2 m : metres) px.push_back(view.toPixels(m));
  return px;
}

void addDiamond(TriangleBatch& batch, const ViewTransform& view, Vec2 at, bool along_x) {
  const double a = 0.013, b = 0.007;  // half length along the rail, half width across
  const Vec2 u = along_x ? Vec2{a, 0.0} : Vec2{0.0, a};
  const Vec2 v = along_x ? Vec2{0.0, b} : Vec2{b, 0.0};
  batch.quad(view.toPixels(at + u), view.toPixels(at + v), view.toPixels(at - u),
             view.toPixels(at - v), toSf(kDiamond));
}

}  // namespace

void TablePainter::build(const TableGeometry& table, const ViewTransform& view) {
  batch_.clear();
  const double hx = table.def.length / 2.0, hy = table.def.width / 2.0;
  const double rail = SceneLayout::kRail;

  // Wood, with a darker edge.
  const Vec2 outer_tl = view.toPixels({-hx - rail, hy + rail});
  const double ow = view.px(2.0 * (hx + rail)), oh = view.px(2.0 * (hy + rail));
  batch_.roundedRect(outer_tl.x, outer_tl.y, ow, oh, view.px(0.05), toSf(kWoodDark));
  const double e = view.px(kWoodEdge);
  batch_.roundedRect(outer_tl.x + e, outer_tl.y + e, ow - 2 * e, oh - 2 * e, view.px(0.04),
                     toSf(kWood));

  // Diamonds: the long rails in eighths of the length, the short rails in quarters (a snooker
  // table has none).
  const double mid = kCushionDepth + (rail - kCushionDepth) / 2.0;
  const int diamond_rows = table.def.marks == TableMarks::Snooker ? 0 : 8;
  for (int k = 1; k < diamond_rows; ++k) {
    if (k == 4) continue;  // the side pocket
    const double x = -hx + k * table.def.length / 8.0;
    addDiamond(batch_, view, {x, hy + mid}, true);
    addDiamond(batch_, view, {x, -hy - mid}, true);
  }
  for (int k = 1; k < diamond_rows / 2; ++k) {
    const double y = -hy + k * table.def.width / 4.0;
    addDiamond(batch_, view, {hx + mid, y}, false);
    addDiamond(batch_, view, {-hx - mid, y}, false);
  }

  // Cushions, then the pocket openings cut through them, then the cloth.
  const Vec2 c0 = view.toPixels({-hx - kCushionDepth, hy + kCushionDepth});
  const Vec2 c1 = view.toPixels({hx + kCushionDepth, -hy - kCushionDepth});
  batch_.quad(c0, {c1.x, c0.y}, c1, {c0.x, c1.y}, toSf(kCushion));
  // Each opening is the physics' own outline: the jaw faces and the cup behind the mouth,
  // with a rim (the same outline a little larger) round it.
  for (const Pocket& p : table.pockets) {
    const std::vector<Vec2> outline = pocketOutline(table, p);
    double cup = 0.0;
    for (std::size_t i = 1; i + 1 < outline.size(); ++i) {
      cup = std::max(cup, length(outline[i] - p.drop_centre));
    }
    const double grow = cup > 0.0 ? (cup + kPocketRim) / cup : 1.0;
    std::vector<Vec2> rim;
    for (Vec2 q : outline) rim.push_back(p.drop_centre + (q - p.drop_centre) * grow);
    batch_.fan(view.toPixels(p.drop_centre), toPixels(view, rim), toSf(kPocketRimColour));
    batch_.fan(view.toPixels(p.drop_centre), toPixels(view, outline), toSf(kPocket));
  }
  batch_.convex(toPixels(view, clothOutline(table)), toSf(kCloth));

  // A thin shade along each cushion nose gives the cushions an edge.
  const double shade = std::max(1.0, view.px(0.004));
  for (const auto& [a, b] : cushionNoses(table)) {
    const Vec2 inward = -perp(normalized(b - a)) * 0.002;  // the loop runs clockwise
    batch_.line(view.toPixels(a + inward), view.toPixels(b + inward), shade, toSf(kClothShade));
  }

  // The lines and spots the game's rules refer to (head string and foot spot, or baulk line,
  // D and spots).
  const TableMarkings marks = markingsOf(table.def);
  const double line_px = std::max(1.0, view.px(0.003));
  for (const TableMarkings::Line& l : marks.lines) {
    batch_.line(view.toPixels(l.a), view.toPixels(l.b), line_px, toSf(kMarking, 90));
  }
  for (const TableMarkings::Arc& a : marks.arcs) {
    const int pieces = 48;
    for (int i = 0; i < pieces; ++i) {
      const double t0 = a.from + (a.to - a.from) * i / pieces;
      const double t1 = a.from + (a.to - a.from) * (i + 1) / pieces;
      const Vec2 p0 = a.centre + Vec2{std::cos(t0), std::sin(t0)} * a.radius;
      const Vec2 p1 = a.centre + Vec2{std::cos(t1), std::sin(t1)} * a.radius;
      batch_.line(view.toPixels(p0), view.toPixels(p1), line_px, toSf(kMarking, 90));
    }
  }
  for (Vec2 spot : marks.spots) {
    batch_.circle(view.toPixels(spot), std::max(1.5, view.px(0.007)), toSf(kMarking, 160));
  }
}

}  // namespace nineball::render
