#pragma once
// A point or vector in the plane. Plain aggregate so arrays of it stay contiguous.
#include <cmath>

namespace pak {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2& operator+=(Vec2 o) { x += o.x; y += o.y; return *this; }
  constexpr Vec2& operator-=(Vec2 o) { x -= o.x; y -= o.y; return *this; }
  constexpr Vec2& operator*=(double s) { x *= s; y *= s; return *this; }
  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
  friend constexpr Vec2 operator*(Vec2 a, double s) { return {a.x * s, a.y * s}; }
  friend constexpr Vec2 operator*(double s, Vec2 a) { return {a.x * s, a.y * s}; }
  friend constexpr Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
  friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
};

constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
constexpr double lengthSquared(Vec2 a) { return dot(a, a); }
inline double length(Vec2 a) { return std::sqrt(dot(a, a)); }
inline double distance(Vec2 a, Vec2 b) { return length(a - b); }
// Counter-clockwise perpendicular (in a y-up frame).
constexpr Vec2 perp(Vec2 a) { return {-a.y, a.x}; }
inline Vec2 normalized(Vec2 a) {
  double l = length(a);
  return l > 0.0 ? a / l : Vec2{0.0, 0.0};
}
inline Vec2 rotated(Vec2 a, double radians) {
  double c = std::cos(radians), s = std::sin(radians);
  return {c * a.x - s * a.y, s * a.x + c * a.y};
}
// Rotated by a turn given as a unit (cos, sin) pair, with no trigonometry.
constexpr Vec2 rotated(Vec2 a, Vec2 turn) { return {turn.x * a.x - turn.y * a.y, turn.y * a.x + turn.x * a.y}; }

}  // namespace pak
