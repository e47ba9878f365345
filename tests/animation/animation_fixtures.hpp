#pragma once
// Small AnimationPak scenes built in code: a disc container and star elements, so the tests
// need no files.
#include <cmath>
#include <numbers>
#include <string>

#include "pak/animation/animation.hpp"

namespace pak::test {

inline Ring starRing(Vec2 centre, double outer, double inner, int points) {
  Ring ring;
  for (int k = 0; k < 2 * points; ++k) {
    const double a = std::numbers::pi * k / points;
    const double r = k % 2 == 0 ? outer : inner;
    ring.push_back(centre + Vec2{r * std::cos(a), r * std::sin(a)});
  }
  return ring;
}

inline Ring discRing(Vec2 centre, double radius, int n = 72) {
  Ring ring;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * std::numbers::pi * k / n;
    ring.push_back(centre + Vec2{radius * std::cos(a), radius * std::sin(a)});
  }
  return ring;
}

inline ElementArt starElement(const std::string& name) {
  Shape s;
  s.subpaths = {Subpath{starRing({50, 50}, 45, 22, 5), true}};
  s.fill = Color{230, 170, 30, 1.0};
  ElementArt e;
  e.source = name;
  e.name = name;
  e.shapes = {s};
  e.outline = {Polygon{s.subpaths[0].points, {}}};
  return e;
}

// An arrow pointing +x: no symmetry, so its orientation is plain to measure.
inline ElementArt arrowElement() {
  Shape s;
  s.subpaths = {Subpath{Ring{{5, 38}, {62, 38}, {62, 18}, {95, 50}, {62, 82}, {62, 62}, {5, 62}}, true}};
  s.fill = Color{40, 120, 200, 1.0};
  ElementArt e;
  e.source = e.name = "arrow.svg";
  e.shapes = {s};
  e.outline = {Polygon{s.subpaths[0].points, {}}};
  return e;
}

// The rotation (radians; y down, so positive turns clockwise on screen) that best maps an
// element's rest mesh onto slice s of it.
inline double sliceAngle(const AnimatedElement& e, int s) {
  const std::vector<Vec2>& rest = e.mesh.mesh.vertices;
  const std::vector<Vec2>& slice = e.slices[s];
  Vec2 cr, cs;
  for (std::size_t v = 0; v < rest.size(); ++v) cr += rest[v], cs += slice[v];
  cr = cr / static_cast<double>(rest.size()), cs = cs / static_cast<double>(rest.size());
  double c = 0.0, sn = 0.0;
  for (std::size_t v = 0; v < rest.size(); ++v) {
    const Vec2 p = rest[v] - cr, q = slice[v] - cs;
    c += dot(p, q), sn += cross(p, q);
  }
  return std::atan2(sn, c);
}

inline Scene discScene(double radius = 200.0) {
  Scene scene;
  scene.source = "disc";
  scene.container = {Polygon{discRing({250, 250}, radius), {}}};
  return scene;
}

// `count` stars that turn by 72° and pulse over one loop, few slices, a short run.
inline AnimationScript spinningStars(int count, int slices = 8) {
  AnimationScript script;
  script.slices = slices;
  script.frames = 16;
  AnimatedElementSpec spec;
  spec.id = "star";
  spec.svg = "star.svg";
  spec.count = count;
  spec.animation.rotation = {{0.0, 0.0}, {1.0, 72.0}};
  spec.animation.scale = {{0.0, 1.0}, {0.5, 1.2}, {1.0, 1.0}};
  script.elements = {spec};
  return script;
}

inline AnimationOptions quickAnimationOptions() {
  AnimationOptions o;
  o.stop.maxIterations = 60;
  o.run.threads = 1;
  return o;
}

}  // namespace pak::test
