#pragma once

#include <cmath>

#include "nineball/vec2.hpp"

namespace nineball {

/// A 3-D vector of doubles: angular velocities in rad/s, z up.
struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  constexpr Vec3() = default;
  constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

  constexpr Vec3 operator+(Vec3 o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(Vec3 o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  constexpr bool operator==(Vec3 o) const { return x == o.x && y == o.y && z == o.z; }
  constexpr bool operator!=(Vec3 o) const { return !(*this == o); }
};

inline constexpr double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline double length(Vec3 v) {
  return std::sqrt(dot(v, v));
}
inline constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline constexpr Vec3 lift(Vec2 v) {
  return {v.x, v.y, 0.0};
}
inline constexpr Vec2 flat(Vec3 v) {
  return {v.x, v.y};
}

}  // namespace nineball
