#include "app/shot_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

#include "nineball/colours.hpp"
#include "nineball/table_markings.hpp"

namespace nineball::app {
namespace {

// Cushion nose to the wood's outer edge, and the rubber's depth (as the game draws them), m.
constexpr double kRail = 0.12;
constexpr double kCushionDepth = 0.05;
constexpr double kMostPixelsPerMetre = 400.0;
constexpr double kMostTableWidthPx = 1200.0;
constexpr double kTitleHeight = 40.0;
constexpr double kLegendHeight = 70.0;
constexpr double kMargin = 12.0;
// A path point closer than this (px) to the line its neighbours make is left out.
constexpr double kSimplifyPx = 0.15;

const Rgb kWoodDark{66, 36, 18};
const Rgb kLoopLine{14, 70, 40};
const Rgb kMarking{236, 244, 236};

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  // 12.50 -> 12.5, 3.00 -> 3: smaller files, same picture.
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string hex(Rgb c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

bool dark(Rgb c) {
  return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b < 70.0;
}

// Metres to pixels: y up on the table, down in SVG.
struct View {
  double scale;
  double cx, cy;  // the table's centre in px

  Vec2 at(Vec2 m) const { return {cx + m.x * scale, cy - m.y * scale}; }
  double px(double metres) const { return metres * scale; }
};

std::string point(Vec2 p) {
  return num(p.x) + "," + num(p.y);
}

std::string points(const View& v, const std::vector<Vec2>& metres) {
  std::string out;
  for (Vec2 m : metres) out += (out.empty() ? "" : " ") + point(v.at(m));
  return out;
}

double distanceToLine(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len = length(ab);
  if (len == 0.0) return length(p - a);
  return std::abs(cross(ab, p - a)) / len;
}

// Douglas-Peucker: the fewest points that stay within kSimplifyPx of the polyline.
void simplify(const std::vector<Vec2>& in, std::size_t first, std::size_t last,
              std::vector<bool>& keep) {
  if (last <= first + 1) return;
  double worst = 0.0;
  std::size_t at = first;
  for (std::size_t i = first + 1; i < last; ++i) {
    const double d = distanceToLine(in[i], in[first], in[last]);
    if (d > worst) {
      worst = d;
      at = i;
    }
  }
  if (worst <= kSimplifyPx) return;
  keep[at] = true;
  simplify(in, first, at, keep);
  simplify(in, at, last, keep);
}

std::vector<Vec2> simplified(const std::vector<Vec2>& px) {
  if (px.size() < 3) return px;
  std::vector<bool> keep(px.size(), false);
  keep.front() = keep.back() = true;
  simplify(px, 0, px.size() - 1, keep);
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < px.size(); ++i) {
    if (keep[i]) out.push_back(px[i]);
  }
  return out;
}

bool moves(const BallTrace& b) {
  for (std::size_t i = 1; i < b.size(); ++i) {
    if (b.x[i] != b.x[0] || b.y[i] != b.y[0]) return true;
  }
  return false;
}

enum class Stroke { None, Dashed, Solid };

Stroke strokeOf(TracePhase p) {
  if (p == TracePhase::Sliding) return Stroke::Dashed;
  if (p == TracePhase::Rolling) return Stroke::Solid;
  return Stroke::None;
}

// One run of the path in one style, drawn twice: a casing that lifts it off the cloth, then
// the ball's colour (a stripe: its colour with a white core).
void drawRun(std::ostringstream& svg, const std::vector<Vec2>& px, Stroke stroke, int id) {
  if (px.size() < 2) return;
  std::string pts;
  for (Vec2 p : simplified(px)) pts += (pts.empty() ? "" : " ") + point(p);
  const Rgb colour = ballColour(id);
  const std::string dash = stroke == Stroke::Dashed ? " stroke-dasharray=\"7,5\"" : "";
  svg << "<polyline points=\"" << pts << "\" stroke=\"" << (dark(colour) ? "#ffffff" : "#000000")
      << "\" stroke-opacity=\"" << (dark(colour) ? "0.8" : "0.35") << "\" stroke-width=\"4.2\""
      << dash << "/>\n"
      << "<polyline points=\"" << pts << "\" stroke=\"" << hex(colour) << "\" stroke-width=\"2.6\""
      << dash << "/>\n";
  if (isStripe(id)) {
    svg << "<polyline points=\"" << pts << "\" stroke=\"#ffffff\" stroke-width=\"0.9\"" << dash
        << "/>\n";
  }
}

void drawPath(std::ostringstream& svg, const View& view, const BallTrace& b) {
  svg << "<g class=\"ball-path\" data-ball=\"" << b.id
      << "\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  std::vector<Vec2> run;
  Stroke style = Stroke::None;
  // The piece from sample i to i + 1 is in the phase sample i starts.
  for (std::size_t i = 0; i + 1 < b.size(); ++i) {
    const Stroke s = strokeOf(b.phase[i]);
    if (s != style) {
      drawRun(svg, run, style, b.id);
      run.clear();
      style = s;
    }
    if (s == Stroke::None) continue;
    if (run.empty()) run.push_back(view.at({b.x[i], b.y[i]}));
    run.push_back(view.at({b.x[i + 1], b.y[i + 1]}));
  }
  drawRun(svg, run, style, b.id);
  svg << "</g>\n";
}

void drawBall(std::ostringstream& svg, const View& view, Vec2 at, int id, double radius,
              const std::string& clip_id) {
  const Vec2 c = view.at(at);
  const double r = view.px(radius);
  const Rgb colour = ballColour(id);
  if (isStripe(id)) {
    svg << "<clipPath id=\"" << clip_id << "\"><circle cx=\"" << num(c.x) << "\" cy=\"" << num(c.y)
        << "\" r=\"" << num(r) << "\"/></clipPath>\n"
        << "<circle cx=\"" << num(c.x) << "\" cy=\"" << num(c.y) << "\" r=\"" << num(r)
        << "\" fill=\"" << hex(kCueBallColour) << "\"/>\n"
        << "<rect x=\"" << num(c.x - r) << "\" y=\"" << num(c.y - r * kStripeHalfHeight)
        << "\" width=\"" << num(2 * r) << "\" height=\"" << num(2 * r * kStripeHalfHeight)
        << "\" fill=\"" << hex(colour) << "\" clip-path=\"url(#" << clip_id << ")\"/>\n"
        << "<circle cx=\"" << num(c.x) << "\" cy=\"" << num(c.y) << "\" r=\"" << num(r)
        << "\" fill=\"none\" stroke=\"#111111\" stroke-width=\"0.8\"/>\n";
  } else {
    svg << "<circle cx=\"" << num(c.x) << "\" cy=\"" << num(c.y) << "\" r=\"" << num(r)
        << "\" fill=\"" << hex(colour) << "\" stroke=\"#111111\" stroke-width=\"0.8\"/>\n";
  }
  if (id == kCueBall) return;
  svg << "<circle cx=\"" << num(c.x) << "\" cy=\"" << num(c.y) << "\" r=\""
      << num(r * kNumberDiscRadius * 1.25) << "\" fill=\"" << hex(kNumberDisc) << "\"/>\n"
      << "<text x=\"" << num(c.x) << "\" y=\"" << num(c.y + r * 0.32) << "\" font-size=\""
      << num(r * 0.95) << "\" font-weight=\"bold\" text-anchor=\"middle\" fill=\"#111111\">" << id
      << "</text>\n";
}

// The markers, each one element of class "event <type>", centred on (0, 0) and moved there.
std::string marker(EventType type, Vec2 at) {
  std::ostringstream m;
  const std::string move = " transform=\"translate(" + point(at) + ")\"";
  switch (type) {
    case EventType::BallBall:
      m << "<circle class=\"event ball\"" << move
        << " r=\"4.5\" fill=\"#ffffff\" stroke=\"#d40000\" stroke-width=\"2.2\"/>";
      break;
    case EventType::Cushion:
      m << "<path class=\"event cushion\"" << move
        << " d=\"M0,-5.5 L5.5,0 L0,5.5 L-5.5,0 Z\" fill=\"#22d3ee\" stroke=\"#083344\""
           " stroke-width=\"1.2\"/>";
      break;
    case EventType::Pocket:
      m << "<path class=\"event pocket\"" << move
        << " d=\"M-5.5,-5.5 L5.5,5.5 M-5.5,5.5 L5.5,-5.5\" stroke=\"#ff3df5\""
           " stroke-width=\"3.2\" stroke-linecap=\"round\"/>";
      break;
    case EventType::Miscue:
      m << "<path class=\"event miscue\"" << move
        << " d=\"M0,-6 L5.5,4 L-5.5,4 Z\" fill=\"#ff9f1c\" stroke=\"#5a2d00\""
           " stroke-width=\"1.2\"/>";
      break;
    case EventType::Airborne:
      m << "<path class=\"event airborne\"" << move
        << " d=\"M0,-6 L4,2 L-4,2 Z\" fill=\"none\" stroke=\"#facc15\" stroke-width=\"1.6\"/>";
      break;
    case EventType::Land:
      m << "<circle class=\"event land\"" << move
        << " r=\"3.5\" fill=\"none\" stroke=\"#facc15\" stroke-width=\"1.6\"/>";
      break;
    case EventType::OffTable:
      m << "<path class=\"event off_table\"" << move
        << " d=\"M-6,-6 L6,6 M-6,6 L6,-6\" stroke=\"#ef4444\" stroke-width=\"3.2\""
           " stroke-linecap=\"round\"/>";
      break;
    case EventType::AllAtRest:
      break;
  }
  return m.str();
}

const BallTrace* traceOf(const Trace& trace, int id) {
  for (const BallTrace& b : trace.balls) {
    if (b.id == id) return &b;
  }
  return nullptr;
}

// Where a ball was at an event's instant (every event instant is sampled).
std::optional<Vec2> positionAt(const Trace& trace, int id, double t) {
  const BallTrace* b = traceOf(trace, id);
  if (!b) return std::nullopt;
  const auto it = std::lower_bound(b->t.begin(), b->t.end(), t);
  if (it == b->t.end() || *it != t) return std::nullopt;
  const auto i = static_cast<std::size_t>(it - b->t.begin());
  return Vec2{b->x[i], b->y[i]};
}

void drawTable(std::ostringstream& svg, const View& view, const TableGeometry& table) {
  const double hx = table.def.length / 2.0, hy = table.def.width / 2.0;
  auto rect = [&](double half_x, double half_y, double corner, Rgb fill) {
    const Vec2 tl = view.at({-half_x, half_y});
    svg << "<rect x=\"" << num(tl.x) << "\" y=\"" << num(tl.y) << "\" width=\""
        << num(view.px(2 * half_x)) << "\" height=\"" << num(view.px(2 * half_y)) << "\" rx=\""
        << num(view.px(corner)) << "\" fill=\"" << hex(fill) << "\"/>\n";
  };
  rect(hx + kRail, hy + kRail, 0.05, kWoodDark);
  rect(hx + kRail - 0.01, hy + kRail - 0.01, 0.04, kWood);
  rect(hx + kCushionDepth, hy + kCushionDepth, 0.0, kCushion);
  // Diamonds: the long rails in eighths, the short rails in quarters.
  const double mid = kCushionDepth + (kRail - kCushionDepth) / 2.0;
  auto diamond = [&](Vec2 at) {
    const Vec2 c = view.at(at);
    svg << "<circle cx=\"" << num(c.x) << "\" cy=\"" << num(c.y) << "\" r=\"" << num(view.px(0.008))
        << "\" fill=\"" << hex(kDiamond) << "\"/>\n";
  };
  const int diamond_rows = table.def.marks == TableMarks::Snooker ? 0 : 8;  // none on snooker
  for (int k = 1; k < diamond_rows; ++k) {
    if (k == 4) continue;
    diamond({-hx + k * table.def.length / 8.0, hy + mid});
    diamond({-hx + k * table.def.length / 8.0, -hy - mid});
  }
  for (int k = 1; k < diamond_rows / 2; ++k) {
    diamond({hx + mid, -hy + k * table.def.width / 4.0});
    diamond({-hx - mid, -hy + k * table.def.width / 4.0});
  }
  // The openings: each the physics' own outline, jaw faces and cup.
  for (const Pocket& p : table.pockets) {
    svg << "<polygon class=\"pocket\" points=\"" << points(view, pocketOutline(table, p))
        << "\" fill=\"" << hex(kPocket) << "\"/>\n";
  }
  svg << "<polygon points=\"" << points(view, clothOutline(table)) << "\" fill=\"" << hex(kCloth)
      << "\"/>\n";
  // The cushion loop the balls bounce off, exactly as the physics builds it.
  svg << "<polygon class=\"cushion-loop\" points=\"" << points(view, table.cushion_loop)
      << "\" fill=\"none\" stroke=\"" << hex(kLoopLine) << "\" stroke-width=\"1.2\"/>\n";
  const TableMarkings marks = markingsOf(table.def);
  for (const TableMarkings::Line& l : marks.lines) {
    const Vec2 a = view.at(l.a), b = view.at(l.b);
    svg << "<line x1=\"" << num(a.x) << "\" y1=\"" << num(a.y) << "\" x2=\"" << num(b.x)
        << "\" y2=\"" << num(b.y) << "\" stroke=\"" << hex(kMarking)
        << "\" stroke-opacity=\"0.35\" stroke-width=\"1\"/>\n";
  }
  for (const TableMarkings::Arc& arc : marks.arcs) {
    const Vec2 a = view.at(arc.centre + Vec2{std::cos(arc.from), std::sin(arc.from)} * arc.radius);
    const Vec2 b = view.at(arc.centre + Vec2{std::cos(arc.to), std::sin(arc.to)} * arc.radius);
    const double r = length(view.at(arc.centre + Vec2{arc.radius, 0.0}) - view.at(arc.centre));
    // The y axis points down in the picture, so a counter-clockwise arc on the table is drawn
    // clockwise: sweep flag 0.
    svg << "<path d=\"M " << num(a.x) << " " << num(a.y) << " A " << num(r) << " " << num(r)
        << " 0 0 0 " << num(b.x) << " " << num(b.y) << "\" fill=\"none\" stroke=\"" << hex(kMarking)
        << "\" stroke-opacity=\"0.35\" stroke-width=\"1\"/>\n";
  }
  for (Vec2 at : marks.spots) {
    const Vec2 spot = view.at(at);
    svg << "<circle cx=\"" << num(spot.x) << "\" cy=\"" << num(spot.y) << "\" r=\"2.5\" fill=\""
        << hex(kMarking) << "\" fill-opacity=\"0.6\"/>\n";
  }
}

std::string summary(const SimResult& result) {
  int contacts = 0, cushions = 0;
  std::string pocketed;
  for (const Event& e : result.events) {
    contacts += e.type == EventType::BallBall;
    cushions += e.type == EventType::Cushion;
    if (e.type == EventType::Pocket) {
      pocketed += (pocketed.empty() ? "" : ", ") + std::to_string(e.a);
    }
  }
  char time[32];
  std::snprintf(time, sizeof time, "%.2f", result.time);
  auto counted = [](int n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  return std::string(time) + " s (" + simEndName(result.end) +
         "): " + counted(contacts, "ball contact") + ", " + counted(cushions, "cushion") +
         "; pocketed: " + (pocketed.empty() ? "none" : pocketed);
}

void drawLegend(std::ostringstream& svg, double top, bool miscue) {
  double x = kMargin + 4.0;
  const double y = top + 24.0;
  auto label = [&](const std::string& text) {
    svg << "<text x=\"" << num(x) << "\" y=\"" << num(y + 4.0) << "\">" << text << "</text>\n";
    x += 9.0 + 7.0 * static_cast<double>(text.size());
  };
  for (bool sliding : {true, false}) {
    svg << "<line x1=\"" << num(x) << "\" y1=\"" << num(y) << "\" x2=\"" << num(x + 40.0)
        << "\" y2=\"" << num(y) << "\" stroke=\"#333333\" stroke-width=\"2.6\""
        << (sliding ? " stroke-dasharray=\"7,5\"" : "") << "/>\n";
    x += 48.0;
    label(sliding ? "sliding" : "rolling");
  }
  std::vector<std::pair<EventType, const char*>> kinds = {{EventType::BallBall, "ball contact"},
                                                          {EventType::Cushion, "cushion"},
                                                          {EventType::Pocket, "pocket"}};
  if (miscue) kinds.push_back({EventType::Miscue, "miscue"});
  for (const auto& [type, text] : kinds) {
    // The legend's markers are not events: their class says so.
    std::string m = marker(type, {x + 6.0, y});
    m.replace(m.find("class=\"event "), 13, "class=\"legend ");
    svg << m << '\n';
    x += 18.0;
    label(text);
  }
  svg << "<text x=\"" << num(kMargin + 4.0) << "\" y=\"" << num(y + 26.0) << "\" fill=\"#444444\">"
      << "Balls faded where they started, solid where they ended (white: the cue ball); "
         "paths in the ball's colour, to scale.</text>\n";
}

}  // namespace

std::string shotSvg(const Scene& scene, const SimResult& result) {
  const double radius = scene.physics.ball_radius;
  const TableGeometry table = buildTable(scene.table, radius);
  const double w_m = table.def.length + 2.0 * kRail, h_m = table.def.width + 2.0 * kRail;
  const double scale = std::min(kMostPixelsPerMetre, kMostTableWidthPx / w_m);
  const double width = w_m * scale + 2.0 * kMargin;
  const double height = kTitleHeight + h_m * scale + kLegendHeight;
  const View view{scale, width / 2.0, kTitleHeight + h_m * scale / 2.0};
  const Trace empty;
  const Trace& trace = result.trace ? *result.trace : empty;

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\""
      << num(height) << "\" viewBox=\"0 0 " << num(width) << ' ' << num(height)
      << "\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
      << "<text x=\"" << num(kMargin + 4.0) << "\" y=\"26\" font-size=\"15\">" << summary(result)
      << "</text>\n";
  drawTable(svg, view, table);

  std::map<int, bool> moving;
  for (const BallTrace& b : trace.balls) moving[b.id] = moves(b);
  svg << "<g class=\"starts\" opacity=\"0.45\">\n";
  for (const BallState& b : scene.balls) {
    if (!b.pocket && moving[b.id]) {
      drawBall(svg, view, b.pos, b.id, radius, "start" + std::to_string(b.id));
    }
  }
  svg << "</g>\n";
  for (const BallTrace& b : trace.balls) {
    if (moving[b.id]) drawPath(svg, view, b);
  }
  svg << "<g class=\"ends\">\n";
  for (const BallState& b : result.balls) {
    if (!b.pocket) drawBall(svg, view, b.pos, b.id, radius, "end" + std::to_string(b.id));
  }
  svg << "</g>\n<g class=\"events\">\n";
  bool miscue = false;
  for (const Event& e : result.events) {
    if (e.type == EventType::AllAtRest) continue;
    miscue |= e.type == EventType::Miscue;
    std::optional<Vec2> at = positionAt(trace, e.a, e.t);
    if (at && e.type == EventType::BallBall) {
      // The contact point, halfway between the two centres.
      const std::optional<Vec2> other = positionAt(trace, e.b, e.t);
      at = other ? (*at + *other) * 0.5 : std::optional<Vec2>{};
    }
    if (at) svg << marker(e.type, view.at(*at)) << '\n';
  }
  svg << "</g>\n";
  drawLegend(svg, kTitleHeight + h_m * scale, miscue);
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace nineball::app
