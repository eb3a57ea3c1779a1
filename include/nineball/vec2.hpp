#pragma once

#include <cmath>

namespace nineball {

/// A plain 2-D vector of doubles in SI units (metres or metres per second).
struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2() = default;
  constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}

  constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator-() const { return {-x, -y}; }
  constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
  constexpr Vec2 operator/(double s) const { return {x / s, y / s}; }
  Vec2& operator+=(Vec2 o) {
    x += o.x;
    y += o.y;
    return *this;
  }
  Vec2& operator-=(Vec2 o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  constexpr bool operator==(Vec2 o) const { return x == o.x && y == o.y; }
  constexpr bool operator!=(Vec2 o) const { return !(*this == o); }
};

inline constexpr Vec2 operator*(double s, Vec2 v) {
  return v * s;
}
inline constexpr double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
inline constexpr double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
inline double length(Vec2 v) {
  return std::sqrt(dot(v, v));
}
inline Vec2 normalized(Vec2 v) {
  const double l = length(v);
  return l > 0.0 ? v / l : Vec2{};
}
/// The vector turned a quarter turn anticlockwise.
inline constexpr Vec2 perp(Vec2 v) {
  return {-v.y, v.x};
}
inline Vec2 rotated(Vec2 v, double radians) {
  const double c = std::cos(radians), s = std::sin(radians);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}
inline Vec2 fromAngle(double radians) {
  return {std::cos(radians), std::sin(radians)};
}

constexpr double kPi = 3.14159265358979323846;
inline constexpr double degToRad(double d) {
  return d * kPi / 180.0;
}
inline constexpr double radToDeg(double r) {
  return r * 180.0 / kPi;
}

}  // namespace nineball
