#include "render/ball_spin.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::render {
namespace {

// The cue ball's spots: a disc this wide (sin of its angular radius) at each pole.
constexpr double kSpotRadius = 0.22;
constexpr Rgb kInk{20, 20, 20};
constexpr Rgb kWhite{250, 248, 240};

Shade shadeOf(Rgb c) {
  return {c.r / 255.0, c.g / 255.0, c.b / 255.0, 1.0};
}

Orientation multiply(const Orientation& a, const Orientation& b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

Vec3 rotate(const Orientation& q, Vec3 v) {
  // v + 2 u x (u x v + w v), u the vector part.
  const Vec3 u{q.x, q.y, q.z};
  const Vec3 t = cross(u, v) * 2.0;
  return v + t * q.w + cross(u, t);
}

}  // namespace

Orientation Orientation::turned(Vec3 turn) const {
  const double angle = length(turn);
  if (!(angle > 0.0)) return *this;
  const double s = std::sin(0.5 * angle) / angle;
  const Orientation step{std::cos(0.5 * angle), turn.x * s, turn.y * s, turn.z * s};
  Orientation q = multiply(step, *this);
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

Vec3 Orientation::toTable(Vec3 body) const {
  return rotate(*this, body);
}

Vec3 Orientation::toBody(Vec3 table) const {
  return rotate({w, -x, -y, -z}, table);
}

void BallSpins::advance(const std::vector<BallState>& balls, double sim_time) {
  const double dt = started_ ? sim_time - time_ : 0.0;
  const bool forward = dt > 0.0 && dt < 1.0;  // a jump (new rack, replay) turns nothing
  for (const BallState& b : balls) {
    Kept start;
    start.w = b.w;
    start.on_table = !b.pocket;
    auto [it, fresh] = balls_.try_emplace(b.id, start);
    Kept& k = it->second;
    if (!fresh && forward && !b.pocket) k.q = k.q.turned((k.w + b.w) * (0.5 * dt));
    k.w = b.w;
    if (b.pocket && k.on_table && forward) {
      k.dropped = true;
      k.drop = {sim_time, b.pos};
    }
    if (!b.pocket) k.dropped = false;
    k.on_table = !b.pocket;
  }
  time_ = sim_time;
  started_ = true;
}

Orientation BallSpins::of(int id) const {
  const auto it = balls_.find(id);
  return it == balls_.end() ? Orientation{} : it->second.q;
}

const BallSpins::Drop* BallSpins::dropOf(int id) const {
  const auto it = balls_.find(id);
  return it != balls_.end() && it->second.dropped ? &it->second.drop : nullptr;
}

void BallSpins::reset() {
  balls_.clear();
  started_ = false;
}

double glyphScale(double width, double height, double cell) {
  return std::min(0.62 * cell / std::max(height, 1e-9), 0.78 * cell / std::max(width, 1e-9));
}

Vec3 lightDirection() {
  const Vec3 l{-0.35, 0.45, 1.0};
  return l * (1.0 / length(l));
}

Shade surfaceColour(const BallLook& look, int number, Vec3 body, InkSampler ink,
                    const void* glyphs) {
  Shade c = shadeOf(look.colour);
  if (look.stripe && std::abs(body.y) > kStripeHalfHeight) c = shadeOf(kWhite);
  const double pole = std::abs(body.z);
  const double off = std::sqrt(std::max(0.0, 1.0 - pole * pole));  // sin of the angle off it
  if (look.numbered && off < kNumberDiscRadius) {
    c = shadeOf(kWhite);
    // Disc coordinates as read from outside the ball at either pole.
    const double u = (body.z > 0.0 ? body.x : -body.x) / kNumberDiscRadius;
    const double v = body.y / kNumberDiscRadius;
    const double coverage = ink ? ink(glyphs, number, u, v) : 0.0;
    const Shade k = shadeOf(kInk);
    c = {c.r + (k.r - c.r) * coverage, c.g + (k.g - c.g) * coverage, c.b + (k.b - c.b) * coverage,
         1.0};
  } else if (look.spots && off < kSpotRadius) {
    c = shadeOf(kCueSpot);
  }
  return c;
}

Shade lightAt(Shade c, double sx, double sy) {
  const double rr = std::min(1.0, sx * sx + sy * sy);
  const Vec3 n{sx, sy, std::sqrt(1.0 - rr)};
  const Vec3 l = lightDirection();
  const double diffuse = std::max(0.0, dot(n, l));
  // Blinn's half vector with the eye straight above.
  const Vec3 h = (l + Vec3{0.0, 0.0, 1.0}) * (1.0 / length(l + Vec3{0.0, 0.0, 1.0}));
  const double specular = std::pow(std::max(0.0, dot(n, h)), 60.0);
  const double light = 0.42 + 0.68 * diffuse;
  auto lit = [&](double x) { return std::min(1.0, x * light + 0.55 * specular); };
  return {lit(c.r), lit(c.g), lit(c.b), c.a};
}

Rgb litColour(Rgb surface, double sx, double sy) {
  const Shade s = lightAt(shadeOf(surface), sx, sy);
  auto channel = [](double v) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(255.0 * v), 0L, 255L));
  };
  return {channel(s.r), channel(s.g), channel(s.b)};
}

Shade litBall(const BallLook& look, int number, const Orientation& q, double sx, double sy,
              double edge, InkSampler ink, const void* glyphs) {
  const double rr = sx * sx + sy * sy;
  if (rr >= 1.0) return {};
  const Vec3 n{sx, sy, std::sqrt(1.0 - rr)};
  Shade c = lightAt(surfaceColour(look, number, q.toBody(n), ink, glyphs), sx, sy);
  c.a = std::clamp((1.0 - std::sqrt(rr)) * edge, 0.0, 1.0);
  return c;
}

}  // namespace nineball::render
