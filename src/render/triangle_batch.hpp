#pragma once

#include <SFML/Graphics/Color.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <vector>

#include "nineball/vec2.hpp"
#include "render/palette.hpp"

namespace nineball::render {

/// An SFML colour from a palette colour.
inline sf::Color toSf(Rgb c, std::uint8_t alpha = 255) {
  return {c.r, c.g, c.b, alpha};
}
/// An SFML point from pixel coordinates.
inline sf::Vector2f toSf(Vec2 p) {
  return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

/// Shapes in pixel coordinates gathered into one triangle list: one draw call for many.
class TriangleBatch {
 public:
  void clear() { vertices_.clear(); }
  /// A filled circle; `segments` 0 picks a count from the radius.
  void circle(Vec2 centre, double radius, sf::Color colour, int segments = 0);
  /// A ring between two radii.
  void ring(Vec2 centre, double inner, double outer, sf::Color colour, int segments = 0);
  /// The part of a ring between two angles (rad, counter-clockwise in the window's axes).
  void arc(Vec2 centre, double inner, double outer, double from, double to, sf::Color colour);
  /// A convex polygon, as a fan from its first point.
  void convex(const std::vector<Vec2>& points, sf::Color colour);
  /// A fan of triangles from `centre` over the closed outline `points`.
  void fan(Vec2 centre, const std::vector<Vec2>& points, sf::Color colour);
  void quad(Vec2 a, Vec2 b, Vec2 c, Vec2 d, sf::Color colour);
  /// A straight line `width` pixels wide.
  void line(Vec2 a, Vec2 b, double width, sf::Color colour);
  /// The same with edges that fade out over a pixel (antialiased: no multisampling needed).
  void softLine(Vec2 a, Vec2 b, double width, sf::Color colour);
  /// A ring whose edges fade out over a pixel.
  void softRing(Vec2 centre, double inner, double outer, sf::Color colour);
  /// An axis-aligned rectangle with rounded corners.
  void roundedRect(double left, double top, double width, double height, double radius,
                   sf::Color colour);

  void draw(sf::RenderTarget& target) const;

 private:
  void band(Vec2 centre, double inner, double outer, double from, double to, int n,
            sf::Color colour);
  void triangle(Vec2 a, Vec2 b, Vec2 c, sf::Color colour);
  // A quad whose colour runs from `from` (a, b) to `to` (c, d).
  void fade(Vec2 a, Vec2 b, Vec2 c, Vec2 d, sf::Color from, sf::Color to);
  std::vector<sf::Vertex> vertices_;
};

/// Segments for a smooth circle of this radius in pixels.
int circleSegments(double radius);

}  // namespace nineball::render
