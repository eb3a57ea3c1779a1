#include "render/hud_painter.hpp"

#include <SFML/Graphics/Text.hpp>
#include <algorithm>
#include <cmath>

#include "nineball/ball.hpp"

namespace nineball::render {
namespace {

const sf::Color kText(236, 236, 230);
const sf::Color kDim(150, 156, 160);
const sf::Color kAccent(255, 214, 90);
const sf::Color kFoul(255, 110, 90);
const sf::Color kWin(130, 230, 140);
const sf::Color kPanel(16, 20, 24, 232);
const sf::Color kButton(54, 92, 70);
const sf::Color kGauge(60, 64, 70);

sf::Color toneColour(Tone t) {
  switch (t) {
    case Tone::Foul:
      return kFoul;
    case Tone::Win:
      return kWin;
    case Tone::Warning:
      return kAccent;
    case Tone::Info:
      break;
  }
  return kText;
}

// Green to yellow to red along the gauge.
sf::Color gaugeColour(double f) {
  const auto mix = [](double a, double b, double u) {
    return static_cast<sf::Uint8>(std::lround(a + (b - a) * u));
  };
  if (f < 0.5) return {mix(90, 240, f * 2.0), mix(200, 210, f * 2.0), mix(90, 60, f * 2.0)};
  return {mix(240, 230, f * 2.0 - 1.0), mix(210, 60, f * 2.0 - 1.0), mix(60, 50, f * 2.0 - 1.0)};
}

}  // namespace

void HudPainter::text(sf::RenderTarget& target, const std::string& s, Vec2 at, double size,
                      sf::Color colour, Align align, bool bold, double max_width) {
  sf::Text t(sf::String::fromUtf8(s.begin(), s.end()), bold ? fonts_.bold : fonts_.regular,
             static_cast<unsigned>(std::lround(size)));
  t.setFillColor(colour);
  double w = t.getLocalBounds().width + t.getLocalBounds().left;
  // A long line shrinks to fit its room rather than run into the next thing.
  if (max_width > 0.0 && w > max_width) {
    t.setCharacterSize(static_cast<unsigned>(std::max(8.0, std::floor(size * max_width / w))));
    w = t.getLocalBounds().width + t.getLocalBounds().left;
  }
  double x = at.x;
  if (align == Align::Centre) x -= w / 2.0;
  if (align == Align::Right) x -= w;
  // Whole pixels keep the glyphs sharp.
  t.setPosition(std::round(static_cast<float>(x)), std::round(static_cast<float>(at.y)));
  target.draw(t);
}

void HudPainter::drawPlayers(sf::RenderTarget& target, const ViewTransform& view,
                             const HudState& hud, const HudLayout& layout) {
  const PixelRect band = view.topBand();
  const double size = layout.text_px * 1.15;
  const double y = band.top + band.height / 2.0 - size * 0.95;
  for (int seat = 0; seat < 2; ++seat) {
    const PlayerPanel& p = hud.players[seat];
    const bool left = seat == 0;
    const double x = left ? band.left + layout.text_px : band.left + band.width - layout.text_px;
    const Align align = left ? Align::Left : Align::Right;
    const std::string marker = p.to_move ? (left ? "\u25B6 " : "") : "";
    const std::string tail = p.to_move && !left ? " \u25C0" : "";
    text(target, marker + p.name + tail, {x, y}, size, p.to_move ? kAccent : kDim, align, true);
    std::string line = "racks " + std::to_string(p.racks);
    if (p.fouls > 0) line += "   fouls in a row " + std::to_string(p.fouls);
    text(target, line, {x, y + size * 1.3}, layout.text_px * 0.85, p.fouls > 0 ? kFoul : kDim,
         align);
  }
  const Vec2 centre{band.left + band.width / 2.0, band.top + band.height / 2.0};
  const double r = view.px(0.03);
  if (hud.ball_on > 0) {
    text(target, "ball on", {centre.x - r * 1.6, centre.y - layout.text_px * 0.65}, layout.text_px,
         kText, Align::Right);
    balls_.drawOne(target, hud.ball_on, centre, r);
  }
  text(target, hud.rules, {centre.x + r * 1.6, centre.y - layout.text_px * 0.65},
       layout.text_px * 0.85, kDim);
  text(target, hud.mode, {centre.x + r * 1.6, centre.y + layout.text_px * 0.35},
       layout.text_px * 0.85, kDim);
}

void HudPainter::drawBottom(sf::RenderTarget& target, const HudState& hud,
                            const HudLayout& layout) {
  const PixelRect g = layout.power_bar;
  batch_.clear();
  batch_.roundedRect(g.left, g.top, g.width, g.height, g.height / 2.0, kGauge);
  const double f = std::clamp(hud.power, 0.0, 1.0);
  if (f > 0.0) {
    batch_.roundedRect(g.left, g.top, std::max(g.height, g.width * f), g.height, g.height / 2.0,
                       gaugeColour(f));
  }
  // The spin icon: a cue ball, the ring of the useful range, the tip's dot.
  const Vec2 c = layout.spin_centre;
  const double r = layout.spin_radius;
  batch_.circle(c, r + 1.5, sf::Color(0, 0, 0, 160));
  batch_.circle(c, r, toSf(kCueBallColour));
  batch_.ring(c, r * hud.max_tip - 1.0, r * hud.max_tip, sf::Color(120, 120, 120, 160));
  batch_.line(c - Vec2{r, 0.0}, c + Vec2{r, 0.0}, 1.0, sf::Color(160, 160, 160, 120));
  batch_.line(c - Vec2{0.0, r}, c + Vec2{0.0, r}, 1.0, sf::Color(160, 160, 160, 120));
  const Vec2 dot_px = c + Vec2{hud.tip.x, -hud.tip.y} * r;
  batch_.circle(dot_px, std::max(3.0, r * 0.14), sf::Color(200, 30, 30));
  // The cue seen from the side: the ring of the tilts it can take, the cue at its tilt.
  const double top = degToRad(hud.max_elevation_deg);
  batch_.arc(c, layout.tilt_inner, layout.tilt_outer, kPi + top, kPi, sf::Color(255, 255, 255, 45));
  for (double tick : {0.0, 15.0, 30.0, 45.0, 60.0}) {
    if (tick > hud.max_elevation_deg) break;
    const Vec2 u = HudLayout::tiltDirection(degToRad(tick));
    batch_.line(c + u * layout.tilt_outer, c + u * (layout.tilt_outer + 0.12 * r), 1.0,
                sf::Color(200, 200, 200, 140));
  }
  const Vec2 tilt = HudLayout::tiltDirection(degToRad(hud.elevation_deg));
  batch_.line(c + tilt * (layout.tilt_inner - 1.0), c + tilt * (layout.tilt_outer + 0.25 * r),
              std::max(3.0, 0.09 * r), sf::Color(222, 184, 135));
  batch_.draw(target);

  const double small = layout.text_px * 0.85;
  char speed[32];
  std::snprintf(speed, sizeof speed, "%.1f m/s", hud.speed);
  text(target, std::string("power  ") + speed, {g.left, g.top - small * 1.5}, small, kText);
  text(target, hud.push_out_declared ? "PUSH-OUT declared (P)" : "H help   Esc quit",
       {g.left, g.top + g.height + small * 0.3}, small * 0.9,
       hud.push_out_declared ? kAccent : kDim);

  std::string spin = "centre";
  if (std::abs(hud.tip.y) > 1e-9 || std::abs(hud.tip.x) > 1e-9) {
    char s[64];
    std::snprintf(s, sizeof s, "%s %.1f  %s %.1f", hud.tip.y >= 0 ? "top" : "back",
                  std::abs(hud.tip.y), hud.tip.x >= 0 ? "right" : "left", std::abs(hud.tip.x));
    spin = s;
  }
  // Three lines beside the icon, centred on it: what sets the tip, the tip, the cue's tilt.
  const double labels_right = c.x - layout.tilt_outer - small * 0.6;
  text(target, "spin (T/B, click)", {labels_right, c.y - small * 2.1}, small * 0.9, kDim,
       Align::Right);
  text(target, spin, {labels_right, c.y - small * 0.65}, small * 0.9, kText, Align::Right);
  char tilt_text[48];
  std::snprintf(tilt_text, sizeof tilt_text, "cue %.0f deg (E/Q)", hud.elevation_deg);
  text(target, tilt_text, {labels_right, c.y + small * 0.8}, small * 0.9,
       hud.elevation_deg > 0.0 ? kText : kDim, Align::Right);

  const PixelRect m = layout.message;
  text(target, hud.status, {m.left, m.top + m.height * 0.12}, layout.text_px, kText, Align::Left,
       true, m.width);
  text(target, hud.message, {m.left, m.top + m.height * 0.12 + layout.text_px * 1.5},
       layout.text_px * 0.92, toneColour(hud.tone), Align::Left, false, m.width);
}

void HudPainter::drawOverlay(sf::RenderTarget& target, const HudState& hud,
                             const HudLayout& layout) {
  const PixelRect p = layout.panel;
  const bool big = hud.overlay == Overlay::Help;
  const double top = p.top;
  batch_.clear();
  batch_.roundedRect(p.left, top, p.width, p.height, layout.text_px, kPanel);
  for (const auto& [label, rect] : {std::pair{&hud.button_left, layout.button_left},
                                    std::pair{&hud.button_right, layout.button_right}}) {
    if (!label->empty()) {
      batch_.roundedRect(rect.left, rect.top, rect.width, rect.height, rect.height / 3.0, kButton);
    }
  }
  batch_.draw(target);
  const double x = p.left + layout.text_px * 1.4;
  double y = top + layout.text_px * 1.1;
  const sf::Color title = hud.overlay == Overlay::GameOver ? kWin : kAccent;
  text(target, hud.overlay_title, {x, y}, layout.text_px * 1.3, title, Align::Left, true);
  y += layout.text_px * 2.2;
  const double line_size = big ? layout.text_px * 0.9 : layout.text_px;
  for (const std::string& line : hud.overlay_lines) {
    text(target, line, {x, y}, line_size, kText);
    y += line_size * 1.45;
  }
  for (const auto& [label, rect] : {std::pair{&hud.button_left, layout.button_left},
                                    std::pair{&hud.button_right, layout.button_right}}) {
    if (!label->empty()) {
      text(target, *label,
           {rect.left + rect.width / 2.0, rect.top + rect.height / 2.0 - layout.text_px * 0.65},
           layout.text_px, kText, Align::Centre, true);
    }
  }
}

void HudPainter::draw(sf::RenderTarget& target, const ViewTransform& view, const HudState& hud) {
  const HudLayout layout = HudLayout::of(view, hud.overlay);
  drawPlayers(target, view, hud, layout);
  drawBottom(target, hud, layout);
  if (hud.overlay != Overlay::None) drawOverlay(target, hud, layout);
}

}  // namespace nineball::render
