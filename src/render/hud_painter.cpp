#include "render/hud_painter.hpp"

#include <SFML/Graphics/Text.hpp>
#include <algorithm>
#include <cmath>

#include "nineball/ball.hpp"
#include "render/palette.hpp"

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
const sf::Color kBallOnRing(235, 235, 225, 220);
// Text never shrinks below this many pixels: smaller is unreadable.
constexpr double kMinTextSize = 7.0;

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

// Where to break a line in two: the sentence end nearest the middle, else the nearest space;
// npos when there is neither.
std::size_t splitNearMiddle(const std::string& s) {
  const std::size_t mid = s.size() / 2;
  std::size_t best = std::string::npos;
  auto closer = [&](std::size_t at) {
    const auto d = [mid](std::size_t a) { return a > mid ? a - mid : mid - a; };
    return best == std::string::npos || d(at) < d(best);
  };
  for (std::size_t i = 1; i + 1 < s.size(); ++i) {
    if (s[i] == ' ' && (s[i - 1] == '.' || s[i - 1] == ':' || s[i - 1] == '!') && closer(i)) {
      best = i;
    }
  }
  // A sentence end far from the middle leaves one line as long as before: a space does better.
  if (best != std::string::npos && (best < s.size() / 4 || best > s.size() * 3 / 4)) {
    best = std::string::npos;
  }
  if (best != std::string::npos) return best;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == ' ' && closer(i)) best = i;
  }
  return best;
}

}  // namespace

PixelRect HudPainter::text(sf::RenderTarget& target, const std::string& s, Vec2 at, double size,
                           sf::Color colour, const PixelRect& room, Align align, bool bold) {
  sf::Text t(sf::String::fromUtf8(s.begin(), s.end()), bold ? fonts_.bold : fonts_.regular,
             static_cast<unsigned>(std::lround(size)));
  t.setFillColor(colour);
  auto width = [&t] { return t.getLocalBounds().width + t.getLocalBounds().left; };
  // A long line shrinks to fit its room rather than run into the next thing.
  for (int tries = 0; tries < 4 && width() > room.width && t.getCharacterSize() > kMinTextSize;
       ++tries) {
    const double fit = std::floor(t.getCharacterSize() * room.width / width());
    t.setCharacterSize(static_cast<unsigned>(
        std::clamp(fit, kMinTextSize, static_cast<double>(t.getCharacterSize() - 1))));
  }
  const double w = width();
  double x = at.x;
  if (align == Align::Centre) x -= w / 2.0;
  if (align == Align::Right) x -= w;
  // Whole pixels keep the glyphs sharp.
  t.setPosition(std::round(static_cast<float>(x)), std::round(static_cast<float>(at.y)));
  target.draw(t);
  const sf::FloatRect b = t.getGlobalBounds();
  const PixelRect box{b.left, b.top, b.width, b.height};
  drawn_.push_back({s, box, room});
  return box;
}

double HudPainter::widthOf(const std::string& s, double size) const {
  const sf::Text t(sf::String::fromUtf8(s.begin(), s.end()), fonts_.regular,
                   static_cast<unsigned>(std::lround(size)));
  return t.getLocalBounds().width + t.getLocalBounds().left;
}

void HudPainter::drawPlayers(sf::RenderTarget& target, const ViewTransform& view,
                             const HudState& hud, const HudLayout& layout) {
  const PixelRect band = view.topBand();
  // Three columns: the players at the sides, the table's state between them.
  const double side_w = 0.22 * band.width;
  const double pad = layout.text_px * 0.5;
  const double size = layout.text_px * 1.15;
  const double y = band.top + band.height / 2.0 - size * 0.95;
  for (int seat = 0; seat < 2; ++seat) {
    const PlayerPanel& p = hud.players[seat];
    if (p.name.empty()) continue;  // practice: one player
    const bool left = seat == 0;
    const PixelRect room{left ? band.left + pad : band.left + band.width - side_w - pad, band.top,
                         side_w, band.height};
    const double x = left ? room.left : room.left + room.width;
    const Align align = left ? Align::Left : Align::Right;
    const std::string marker = p.to_move ? (left ? "\u25B6 " : "") : "";
    const std::string tail = p.to_move && !left ? " \u25C0" : "";
    text(target, marker + p.name + tail, {x, y}, size, p.to_move ? kAccent : kDim, room, align,
         true);
    std::string line = p.detail.empty() ? "racks " + std::to_string(p.racks) : p.detail;
    if (p.fouls > 0) line += "   fouls in a row " + std::to_string(p.fouls);
    text(target, line, {x, y + size * 1.3}, layout.text_px * 0.85, p.fouls > 0 ? kFoul : kDim, room,
         align);
  }
  const PixelRect centre{band.left + side_w + 2.0 * pad, band.top,
                         band.width - 2.0 * side_w - 4.0 * pad, band.height};
  const double mid = centre.left + centre.width / 2.0;
  const double r = std::min(view.px(0.03), layout.text_px * 0.75);
  const double row1 = band.top + band.height * 0.3;
  // Row one: the ball on (left of the middle), the rules and who plays (right of it).
  if (hud.ball_on > 0) {
    const PixelRect room{centre.left, band.top, mid - r * 1.6 - centre.left, band.height * 0.6};
    text(target, "ball on", {mid - r * 1.6, row1 - layout.text_px * 0.65}, layout.text_px, kText,
         room, Align::Right);
    // A light ring: the black 8 would hardly show on the dark band.
    batch_.clear();
    batch_.ring({mid, row1}, r + 1.0, r + std::max(2.0, 0.16 * r), kBallOnRing);
    batch_.draw(target);
    drawBallIcon(target, hud.ball_on, {mid, row1}, r);
  }
  const PixelRect info{mid + r * 1.6, band.top, centre.left + centre.width - mid - r * 1.6,
                       band.height * 0.6};
  text(target, hud.rules, {info.left, row1 - layout.text_px * 0.8}, layout.text_px * 0.75, kDim,
       info);
  text(target, hud.mode, {info.left, row1 + layout.text_px * 0.05}, layout.text_px * 0.75, kDim,
       info);
  // Row two: the tray, or carom's count of cushions.
  const PixelRect row2{centre.left, band.top + band.height / 2.0, centre.width, band.height / 2.0};
  if (!hud.carom_count.empty()) {
    const bool point = hud.carom_count.find("POINT") != std::string::npos;
    const bool none = hud.carom_count.find("no point") != std::string::npos;
    text(target, hud.carom_count, {mid, row2.top + row2.height * 0.05}, layout.text_px * 1.05,
         point  ? kWin
         : none ? kFoul
                : kText,
         row2, Align::Centre, true);
    return;
  }
  if (!hud.score_line.empty()) {
    text(target, hud.score_line, {mid, row2.top + row2.height * 0.08}, layout.text_px * 0.95,
         hud.score_call ? kAccent : kText, row2, Align::Centre, true);
    return;
  }
  drawTray(target, hud, row2, r * 0.8);
}

namespace {
// Eight-ball's tray groups: the solids, the 8, the stripes.
int groupIndex(int ball) {
  return ball < 8 ? 0 : ball == 8 ? 1 : 2;
}
}  // namespace

void HudPainter::drawBallIcon(sf::RenderTarget& target, int id, Vec2 centre, double r) {
  // The balls' own number glyphs are sized to fit their disc, two digits too.
  balls_.drawOne(target, id, centre, r);
}

void HudPainter::drawTray(sf::RenderTarget& target, const HudState& hud, const PixelRect& room,
                          double r) {
  if (hud.on_table.empty() && hud.pocketed.empty()) return;
  // The balls still on the table, then a trough of the pocketed ones in the order they fell.
  const std::size_t on = hud.on_table.size(), down = hud.pocketed.size();
  const double gap = r * 0.35;
  // The trough holds every object ball of the rack, so it fills up as they drop.
  const double trough_w = (on + down) * (2.0 * r + gap) + gap;
  // Eight-ball: the groups apart, the 8 between them.
  int splits = 0;
  for (std::size_t i = 1; hud.split_groups && i < on; ++i) {
    if (groupIndex(hud.on_table[i]) != groupIndex(hud.on_table[i - 1])) ++splits;
  }
  const double width = on * (2.0 * r + gap) + splits * r + r + trough_w;
  const double scale = std::min(1.0, room.width / width);
  const double rr = r * scale, g = gap * scale;
  double x = room.left + (room.width - width * scale) / 2.0 + rr;
  const double cy = room.top + room.height * 0.62;
  auto ball = [&](int id, const char* where) {
    drawBallIcon(target, id, {x, cy}, rr);
    drawn_.push_back({std::string(where) + " " + std::to_string(id),
                      {x - rr, cy - rr, 2.0 * rr, 2.0 * rr},
                      room});
    x += 2.0 * rr + g;
  };
  for (std::size_t i = 0; i < on; ++i) {
    if (hud.split_groups && i > 0 &&
        groupIndex(hud.on_table[i]) != groupIndex(hud.on_table[i - 1])) {
      x += rr;
    }
    ball(hud.on_table[i], "on table");
  }
  x += rr * 0.5;
  batch_.clear();
  batch_.roundedRect(x - g, cy - rr - g, trough_w * scale, 2.0 * (rr + g), rr + g,
                     sf::Color(8, 10, 12, 220));
  batch_.draw(target);
  x += rr;
  for (int id : hud.pocketed) ball(id, "pocketed");
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
  batch_.line(c + tilt * (layout.tilt_inner - 1.0),
              c + tilt * (layout.tilt_outer + HudLayout::kTiltMarkReach * r),
              std::max(3.0, 0.09 * r), sf::Color(222, 184, 135));
  batch_.draw(target);

  const double small = layout.text_px * 0.85;
  const PixelRect gauge_room{g.left, g.top - small * 2.0, g.width, g.height + small * 4.0};
  char speed[32];
  std::snprintf(speed, sizeof speed, "%.1f m/s", hud.speed);
  text(target, std::string("power  ") + speed, {g.left, g.top - small * 1.5}, small, kText,
       gauge_room);
  text(target, hud.push_out_declared ? "PUSH-OUT declared (P)" : hud.keys,
       {g.left, g.top + g.height + small * 0.3}, small * 0.9,
       hud.push_out_declared ? kAccent : kDim, gauge_room);

  std::string spin = "centre";
  if (std::abs(hud.tip.y) > 1e-9 || std::abs(hud.tip.x) > 1e-9) {
    char s[64];
    std::snprintf(s, sizeof s, "%s %.1f  %s %.1f", hud.tip.y >= 0 ? "top" : "back",
                  std::abs(hud.tip.y), hud.tip.x >= 0 ? "right" : "left", std::abs(hud.tip.x));
    spin = s;
  }
  // Three lines beside the icon, centred on it: what sets the tip, the tip, the cue's tilt.
  const double labels_right = layout.spin_labels_right;
  const double labels_w = layout.message.left + layout.message.width;
  const PixelRect labels{labels_w + small * 0.5, c.y - small * 2.4,
                         labels_right - labels_w - small * 0.5, small * 4.8};
  text(target, "spin (T/B/L/R, click)", {labels_right, c.y - small * 2.1}, small * 0.9, kDim,
       labels, Align::Right);
  text(target, spin, {labels_right, c.y - small * 0.65}, small * 0.9, kText, labels, Align::Right);
  char tilt_text[48];
  std::snprintf(tilt_text, sizeof tilt_text, "cue %.0f deg (E/Q)", hud.elevation_deg);
  text(target, tilt_text, {labels_right, c.y + small * 0.8}, small * 0.9,
       hud.elevation_deg > 0.0 ? kText : kDim, labels, Align::Right);

  const PixelRect m = layout.message;
  text(target, hud.status, {m.left, m.top + m.height * 0.08}, layout.text_px, kText, m, Align::Left,
       true);
  // A message too long for one line takes two, split at a sentence (or a word) near its middle.
  const Vec2 at{m.left, m.top + m.height * 0.08 + layout.text_px * 1.35};
  const double size = layout.text_px * 0.92;
  const std::size_t split =
      widthOf(hud.message, size) > m.width ? splitNearMiddle(hud.message) : std::string::npos;
  if (split == std::string::npos) {
    text(target, hud.message, at, size, toneColour(hud.tone), m);
  } else {
    // Two lines in the room left under the status line, as large as fit (up to 0.8 of one).
    const double room_left = m.top + m.height - at.y;
    const double small_size = std::min(size * 0.8, room_left / 2.5);
    text(target, hud.message.substr(0, split), at, small_size, toneColour(hud.tone), m);
    text(target, hud.message.substr(split + 1), at + Vec2{0.0, small_size * 1.2}, small_size,
         toneColour(hud.tone), m);
  }
}

void HudPainter::drawOverlay(sf::RenderTarget& target, const HudState& hud,
                             const HudLayout& layout) {
  const PixelRect p = layout.panel;
  const DialogLook look = hud.dialog.value_or(DialogLook{});
  batch_.clear();
  batch_.roundedRect(p.left, p.top, p.width, p.height, layout.text_px, kPanel);
  const bool buttons = !hud.button_left.empty() || !hud.button_right.empty();
  for (const auto& [label, rect] : {std::pair{&hud.button_left, layout.button_left},
                                    std::pair{&hud.button_middle, layout.button_middle},
                                    std::pair{&hud.button_right, layout.button_right}}) {
    if (!label->empty()) {
      batch_.roundedRect(rect.left, rect.top, rect.width, rect.height, rect.height / 3.0, kButton);
    }
  }
  batch_.draw(target);
  // The text's room: inside the panel's padding, above the buttons.
  const double pad = layout.text_px * 1.2;
  const double bottom = buttons ? layout.button_left.top - pad * 0.4 : p.top + p.height - pad * 0.6;
  const PixelRect room{p.left + pad, p.top + pad * 0.5, p.width - 2.0 * pad,
                       bottom - p.top - pad * 0.5};
  const double x = room.left;
  double title_size = layout.text_px * 1.3;
  double line_size = look.small_print ? layout.text_px * 0.9 : layout.text_px;
  // Lines that would not fit the room's height all shrink together.
  const double need = title_size * 1.7 + line_size * 1.45 * hud.overlay_lines.size();
  if (need > room.height) {
    const double k = room.height / need;
    title_size *= k;
    line_size *= k;
  }
  double y = room.top + title_size * 0.2;
  const sf::Color title = look.win ? kWin : kAccent;
  text(target, hud.overlay_title, {x, y}, title_size, title, room, Align::Left, true);
  y += title_size * 1.7;
  for (const std::string& line : hud.overlay_lines) {
    text(target, line, {x, y}, line_size, kText, room);
    y += line_size * 1.45;
  }
  for (const auto& [label, rect] : {std::pair{&hud.button_left, layout.button_left},
                                    std::pair{&hud.button_middle, layout.button_middle},
                                    std::pair{&hud.button_right, layout.button_right}}) {
    if (!label->empty()) {
      const PixelRect inner{rect.left + rect.height * 0.3, rect.top, rect.width - rect.height * 0.6,
                            rect.height};
      text(target, *label,
           {rect.left + rect.width / 2.0, rect.top + rect.height / 2.0 - layout.text_px * 0.65},
           layout.text_px, kText, inner, Align::Centre, true);
    }
  }
}

void HudPainter::draw(sf::RenderTarget& target, const ViewTransform& view, const HudState& hud) {
  drawn_.clear();
  const HudLayout layout =
      HudLayout::of(view, hud.dialog, hud.keep_clear, !hud.button_middle.empty());
  drawPlayers(target, view, hud, layout);
  drawBottom(target, hud, layout);
  if (hud.dialog) drawOverlay(target, hud, layout);
}

void HudPainter::drawDialog(sf::RenderTarget& target, const ViewTransform& view,
                            const HudState& hud) {
  if (!hud.dialog) return;
  drawOverlay(target, hud,
              HudLayout::of(view, hud.dialog, hud.keep_clear, !hud.button_middle.empty()));
}

}  // namespace nineball::render
