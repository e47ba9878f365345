#pragma once
// A point or vector in (x, y, t) spacetime, for AnimationPak. Plain aggregate like Vec2.
#include <cmath>

#include "pak/geom/vec2.hpp"

namespace pak {

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double t = 0.0;

  constexpr Vec3& operator+=(Vec3 o) { x += o.x; y += o.y; t += o.t; return *this; }
  constexpr Vec3& operator-=(Vec3 o) { x -= o.x; y -= o.y; t -= o.t; return *this; }
  constexpr Vec3& operator*=(double s) { x *= s; y *= s; t *= s; return *this; }
  friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.t + b.t}; }
  friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.t - b.t}; }
  friend constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.t}; }
  friend constexpr Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.t * s}; }
  friend constexpr Vec3 operator*(double s, Vec3 a) { return {a.x * s, a.y * s, a.t * s}; }
  friend constexpr Vec3 operator/(Vec3 a, double s) { return {a.x / s, a.y / s, a.t / s}; }
  friend constexpr bool operator==(Vec3 a, Vec3 b) = default;
};

constexpr double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.t * b.t; }
constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.t - a.t * b.y, a.t * b.x - a.x * b.t, a.x * b.y - a.y * b.x};
}
constexpr double lengthSquared(Vec3 a) { return dot(a, a); }
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline double distance(Vec3 a, Vec3 b) { return length(a - b); }
constexpr Vec2 spatial(Vec3 a) { return {a.x, a.y}; }

}  // namespace pak
