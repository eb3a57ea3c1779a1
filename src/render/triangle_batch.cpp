#include "render/triangle_batch.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace nineball::render {

int circleSegments(double radius) {
  return std::clamp(static_cast<int>(std::ceil(radius * 1.2)), 12, 96);
}

void TriangleBatch::triangle(Vec2 a, Vec2 b, Vec2 c, sf::Color colour) {
  vertices_.emplace_back(toSf(a), colour);
  vertices_.emplace_back(toSf(b), colour);
  vertices_.emplace_back(toSf(c), colour);
}

void TriangleBatch::circle(Vec2 centre, double radius, sf::Color colour, int segments) {
  const int n = segments > 0 ? segments : circleSegments(radius);
  Vec2 prev = centre + Vec2{radius, 0.0};
  for (int i = 1; i <= n; ++i) {
    const Vec2 next = centre + fromAngle(2.0 * kPi * i / n) * radius;
    triangle(centre, prev, next, colour);
    prev = next;
  }
}

void TriangleBatch::ring(Vec2 centre, double inner, double outer, sf::Color colour, int segments) {
  band(centre, inner, outer, 0.0, 2.0 * kPi, segments > 0 ? segments : circleSegments(outer),
       colour);
}

void TriangleBatch::arc(Vec2 centre, double inner, double outer, double from, double to,
                        sf::Color colour) {
  const double share = std::abs(to - from) / (2.0 * kPi);
  band(centre, inner, outer, from, to,
       std::max(2, static_cast<int>(std::ceil(circleSegments(outer) * share))), colour);
}

void TriangleBatch::band(Vec2 centre, double inner, double outer, double from, double to, int n,
                         sf::Color colour) {
  for (int i = 0; i < n; ++i) {
    const Vec2 u0 = fromAngle(from + (to - from) * i / n);
    const Vec2 u1 = fromAngle(from + (to - from) * (i + 1) / n);
    quad(centre + u0 * inner, centre + u0 * outer, centre + u1 * outer, centre + u1 * inner,
         colour);
  }
}

void TriangleBatch::convex(const std::vector<Vec2>& points, sf::Color colour) {
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    triangle(points[0], points[i], points[i + 1], colour);
  }
}

void TriangleBatch::fan(Vec2 centre, const std::vector<Vec2>& points, sf::Color colour) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    triangle(centre, points[i], points[(i + 1) % points.size()], colour);
  }
}

void TriangleBatch::quad(Vec2 a, Vec2 b, Vec2 c, Vec2 d, sf::Color colour) {
  triangle(a, b, c, colour);
  triangle(a, c, d, colour);
}

void TriangleBatch::line(Vec2 a, Vec2 b, double width, sf::Color colour) {
  const Vec2 n = perp(normalized(b - a)) * (width / 2.0);
  quad(a + n, b + n, b - n, a - n, colour);
}

void TriangleBatch::fade(Vec2 a, Vec2 b, Vec2 c, Vec2 d, sf::Color from, sf::Color to) {
  for (const auto& [p, col] :
       {std::pair<Vec2, sf::Color>{a, from}, {b, from}, {c, to}, {a, from}, {c, to}, {d, to}}) {
    vertices_.emplace_back(toSf(p), col);
  }
}

void TriangleBatch::softLine(Vec2 a, Vec2 b, double width, sf::Color colour) {
  const Vec2 n = perp(normalized(b - a));
  const double core = std::max(0.0, width / 2.0 - 0.5), edge = width / 2.0 + 0.5;
  sf::Color clear = colour;
  clear.a = 0;
  if (core > 0.0) quad(a + n * core, b + n * core, b - n * core, a - n * core, colour);
  fade(a + n * core, b + n * core, b + n * edge, a + n * edge, colour, clear);
  fade(a - n * core, b - n * core, b - n * edge, a - n * edge, colour, clear);
}

void TriangleBatch::softRing(Vec2 centre, double inner, double outer, sf::Color colour) {
  const int n = circleSegments(outer);
  const double core_in = std::min(inner + 0.5, 0.5 * (inner + outer));
  const double core_out = std::max(outer - 0.5, core_in);
  sf::Color clear = colour;
  clear.a = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2 u0 = fromAngle(2.0 * kPi * i / n), u1 = fromAngle(2.0 * kPi * (i + 1) / n);
    if (core_out > core_in) {
      quad(centre + u0 * core_in, centre + u0 * core_out, centre + u1 * core_out,
           centre + u1 * core_in, colour);
    }
    fade(centre + u0 * core_out, centre + u1 * core_out, centre + u1 * (outer + 0.5),
         centre + u0 * (outer + 0.5), colour, clear);
    fade(centre + u0 * core_in, centre + u1 * core_in, centre + u1 * std::max(0.0, inner - 0.5),
         centre + u0 * std::max(0.0, inner - 0.5), colour, clear);
  }
}

void TriangleBatch::roundedRect(double left, double top, double width, double height, double radius,
                                sf::Color colour) {
  radius = std::min({radius, width / 2.0, height / 2.0});
  std::vector<Vec2> outline;
  const Vec2 corners[4] = {{left + width - radius, top + radius},
                           {left + width - radius, top + height - radius},
                           {left + radius, top + height - radius},
                           {left + radius, top + radius}};
  constexpr int kCornerSegments = 6;
  for (int c = 0; c < 4; ++c) {
    for (int i = 0; i <= kCornerSegments; ++i) {
      // Pixel y points down: corners go right-top, right-bottom, left-bottom, left-top.
      const double a = -kPi / 2.0 + kPi / 2.0 * (c + static_cast<double>(i) / kCornerSegments);
      outline.push_back(corners[c] + fromAngle(a) * radius);
    }
  }
  convex(outline, colour);
}

void TriangleBatch::draw(sf::RenderTarget& target) const {
  if (!vertices_.empty()) {
    target.draw(vertices_.data(), vertices_.size(), sf::Triangles);
  }
}

}  // namespace nineball::render
