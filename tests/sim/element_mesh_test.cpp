#include "pak/sim/element_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "pak/geom/verify.hpp"
#include "pak/io/scene_loader.hpp"
#include "repulsion/mesh_fixtures.hpp"

using namespace pak;

namespace {

Shape filledShape(Ring ring) {
  Shape s;
  s.subpaths.push_back({std::move(ring), true});
  s.fill = Color{200, 40, 40, 1.0};
  return s;
}

int countKind(const ElementMesh& m, SpringKind kind) {
  int n = 0;
  for (const Spring& s : m.springs) n += s.kind == kind ? 1 : 0;
  return n;
}

}  // namespace

TEST(ElementMesh, SquareSkinMeshAndSprings) {
  Ring square = {{-50, -50}, {50, -50}, {50, 50}, {-50, 50}};
  ElementMeshOptions options;
  options.gap = 10.0;
  options.spacing = 10.0;
  ElementMesh m = buildElementMesh({filledShape(square)}, Region{Polygon{square, {}}}, options);
  MeshCheck check = verifyMesh(m.mesh);
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems.front());
  // Skin: the square offset by 5 with round corners, perimeter 400 + 10π ≈ 431.4.
  EXPECT_NEAR(m.boundaryCount, 43, 2);
  double skinArea = 110.0 * 110.0 - (4.0 - std::numbers::pi) * 25.0;
  EXPECT_NEAR(m.skinArea, skinArea, 0.02 * skinArea);
  EXPECT_DOUBLE_EQ(m.artArea, 10000.0);
  EXPECT_GT(m.mesh.vertices.size(), static_cast<std::size_t>(m.boundaryCount));  // interior points
  EXPECT_GT(countKind(m, SpringKind::Shear), 0);
  for (const Spring& s : m.springs) EXPECT_GT(s.restLength, 0.0);
  // Boundary ring first, positively oriented.
  Ring ring(m.mesh.vertices.begin(), m.mesh.vertices.begin() + m.boundaryCount);
  EXPECT_GT(signedArea(ring), 0.0);
}

TEST(ElementMesh, ConcaveElementGetsNegativeSpaceSprings) {
  // A U shape: its notch is inside the convex hull.
  Ring u = {{0, 0}, {100, 0}, {100, 100}, {70, 100}, {70, 30}, {30, 30}, {30, 100}, {0, 100}};
  ElementMeshOptions options;
  options.gap = 6.0;
  options.spacing = 8.0;
  ElementMesh m = buildElementMesh({filledShape(u)}, Region{Polygon{u, {}}}, options);
  EXPECT_TRUE(verifyMesh(m.mesh).ok);
  EXPECT_GT(countKind(m, SpringKind::NegativeSpace), 0);
  // No mesh triangle covers the notch.
  for (const auto& t : m.mesh.triangles) {
    Vec2 c = (m.mesh.vertices[t[0]] + m.mesh.vertices[t[1]] + m.mesh.vertices[t[2]]) / 3.0;
    EXPECT_FALSE(c.x > 40 && c.x < 60 && c.y > 45) << c.x << "," << c.y;
  }
}

TEST(ElementMesh, ReplayReproducesArtAndFollowsRigidMotion) {
  Ring leaf = {{0, 0}, {40, -20}, {80, 0}, {40, 20}};
  Shape art = filledShape(leaf);
  ElementMeshOptions options;
  options.gap = 4.0;
  options.spacing = 6.0;
  ElementMesh m = buildElementMesh({art}, Region{Polygon{leaf, {}}}, options);
  std::vector<Vec2> out;
  replayArt(m, m.mesh.vertices.data(), out);
  ASSERT_EQ(out.size(), leaf.size());
  for (std::size_t i = 0; i < leaf.size(); ++i) {
    EXPECT_NEAR(out[i].x, leaf[i].x, 1e-9);
    EXPECT_NEAR(out[i].y, leaf[i].y, 1e-9);
  }
  // Rotate by 90° and translate: the art moves rigidly with the mesh.
  std::vector<Vec2> moved;
  for (Vec2 v : m.mesh.vertices) moved.push_back(rotated(v, std::numbers::pi / 2) + Vec2{5, 7});
  replayArt(m, moved.data(), out);
  for (std::size_t i = 0; i < leaf.size(); ++i) {
    Vec2 expected = rotated(leaf[i], std::numbers::pi / 2) + Vec2{5, 7};
    EXPECT_NEAR(out[i].x, expected.x, 1e-9);
    EXPECT_NEAR(out[i].y, expected.y, 1e-9);
  }
}

// The drawn art follows any affine deformation exactly, as the thesis's linear map does; on a
// mesh with vertex jitter it is smoother than the linear map (its second differences are
// smaller) and stays near it.
TEST(ElementMesh, DrawnArtIsExactForAffineMapsAndSmoothsMeshJitter) {
  Ring ellipse;
  for (int k = 0; k < 240; ++k) {
    const double a = 2 * std::numbers::pi * k / 240;
    ellipse.push_back({60 * std::cos(a), 35 * std::sin(a)});
  }
  ElementMeshOptions options;
  options.gap = 6.0;
  options.spacing = 8.0;
  const ElementMesh m = buildElementMesh({filledShape(ellipse)}, Region{Polygon{ellipse, {}}}, options);
  ASSERT_EQ(m.smoothing.offsets.size(), m.mesh.vertices.size() + 1);
  std::vector<Vec2> sheared, drawn, linear;
  for (Vec2 v : m.mesh.vertices) sheared.push_back(Vec2{1.3 * v.x + 0.4 * v.y + 5, -0.2 * v.x + 0.8 * v.y - 3});
  replayDrawnArt(m, sheared.data(), false, drawn);
  replayArt(m, sheared.data(), linear);
  ASSERT_EQ(drawn.size(), ellipse.size());
  for (std::size_t i = 0; i < drawn.size(); ++i) EXPECT_LT(distance(drawn[i], linear[i]), 1e-9);

  // Every vertex jittered by up to ±0.6 (deterministically).
  std::vector<Vec2> jittered = m.mesh.vertices;
  for (std::size_t v = 0; v < jittered.size(); ++v)
    jittered[v] += Vec2{0.6 * std::sin(12.9898 * v), 0.6 * std::cos(78.233 * v)};
  replayDrawnArt(m, jittered.data(), false, drawn);
  replayArt(m, jittered.data(), linear);
  auto wobble = [](const std::vector<Vec2>& ring) {  // mean |second difference|
    double sum = 0;
    for (std::size_t i = 0; i < ring.size(); ++i)
      sum += length(ring[(i + ring.size() - 1) % ring.size()] - ring[i] * 2.0 + ring[(i + 1) % ring.size()]);
    return sum / ring.size();
  };
  EXPECT_LT(wobble(drawn), 0.6 * wobble(linear));
  for (std::size_t i = 0; i < drawn.size(); ++i) EXPECT_LT(distance(drawn[i], linear[i]), 1.2);
  // The linear flag gives the thesis's map.
  replayDrawnArt(m, jittered.data(), true, drawn);
  EXPECT_EQ(drawn, linear);
}

TEST(ElementMesh, SeparatePiecesBecomeOneSkin) {
  Ring a = {{0, 0}, {20, 0}, {20, 20}, {0, 20}};
  Ring b = {{30, 0}, {50, 0}, {50, 20}, {30, 20}};
  Polygon skin = elementSkin(Region{Polygon{a, {}}, Polygon{b, {}}}, 4.0, 0.25);
  EXPECT_GE(skin.outer.size(), 4u);
  EXPECT_TRUE(pointInPolygon({10, 10}, skin));
  EXPECT_TRUE(pointInPolygon({40, 10}, skin));
  EXPECT_TRUE(skin.holes.empty());
}

namespace {

// Meshes every element of a library at a typical packing size (skin area about 20,000 in
// canonical units, as for 30 elements in a 1000-wide container) and checks the invariants.
void expectEveryElementMeshes(const Library& library) {
  ASSERT_FALSE(library.empty());
  for (const ElementArt& e : library) {
    double scale = std::sqrt(15000.0 / area(e.outline));
    ElementMesh m = test::centredElementMesh(e, scale, 10.0, 14.0);
    MeshCheck check = verifyMesh(m.mesh);
    EXPECT_TRUE(check.ok) << e.source << ": " << (check.problems.empty() ? "" : check.problems.front());
    EXPECT_GE(m.boundaryCount, 3) << e.source;
    EXPECT_GT(m.skinArea, m.artArea) << e.source;  // the skin encloses the art plus a margin
    EXPECT_EQ(m.bindings.size(), [&] {
      std::size_t n = 0;
      for (const Shape& s : e.shapes)
        for (const Subpath& sub : s.subpaths) n += sub.points.size();
      return n;
    }()) << e.source;
  }
}

}  // namespace

TEST(ElementMesh, EveryBundledExampleElementMeshes) {
  expectEveryElementMeshes(loadLibrary({std::string(PAK_SOURCE_DIR) + "/examples/elements"}));
}

TEST(ElementMesh, EverySharedDataElementMeshes) {
  const std::string data = PAK_SHARED_DATA_DIR;
  if (!std::filesystem::exists(data)) GTEST_SKIP() << "shared data not found at " << data;
  expectEveryElementMeshes(loadLibrary({data + "/repulsionpak/animals", data + "/repulsionpak/small_cat"}));
  Library mdi;
  for (const auto& entry : std::filesystem::directory_iterator(data + "/mdi"))
    if (entry.path().extension() == ".svg") mdi.push_back(loadLibrary({entry.path().string()}).front());
  expectEveryElementMeshes(mdi);
}

namespace {

// A five-pointed star about the origin (outer radius 60, inner 25).
Ring star5() {
  Ring ring;
  for (int k = 0; k < 10; ++k) {
    const double angle = std::numbers::pi / 2 + k * std::numbers::pi / 5, r = k % 2 == 0 ? 60.0 : 25.0;
    ring.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  return ring;
}

// The index of the vertex at p, or -1.
int vertexAt(const ElementMesh& m, Vec2 p, double tolerance) {
  for (std::size_t v = 0; v < m.mesh.vertices.size(); ++v)
    if (distance(m.mesh.vertices[v], p) <= tolerance) return static_cast<int>(v);
  return -1;
}

}  // namespace

TEST(ElementMesh, SymmetricMeshTurnsOntoItself) {
  const Ring star = star5();
  ElementMeshOptions options;
  options.gap = 6.0;
  options.spacing = 8.0;
  options.symmetry = 5;
  ElementMesh m = buildElementMesh({filledShape(star)}, Region{Polygon{star, {}}}, options);
  ASSERT_EQ(m.symmetry, 5);
  MeshCheck check = verifyMesh(m.mesh);
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems.front());
  EXPECT_EQ(m.boundaryCount % 5, 0);
  EXPECT_GT(m.mesh.vertices.size(), static_cast<std::size_t>(m.boundaryCount) + 5);
  // A turn by 72° maps every vertex onto another, skin onto skin, one to one; the ring keeps
  // its order (vertex i goes to i + a fifth of the ring).
  std::vector<int> image;
  for (Vec2 p : m.mesh.vertices) image.push_back(vertexAt(m, rotated(p, 2 * std::numbers::pi / 5), 1e-9));
  std::vector<int> sorted = image;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t v = 0; v < sorted.size(); ++v) ASSERT_EQ(sorted[v], static_cast<int>(v));
  const int fifth = m.boundaryCount / 5;
  for (int v = 0; v < m.boundaryCount; ++v) EXPECT_EQ(image[v], (v + fifth) % m.boundaryCount);
  // Interior samples keep most of the blue noise's spacing across the sectors' edges.
  for (std::size_t a = static_cast<std::size_t>(m.boundaryCount); a < m.mesh.vertices.size(); ++a)
    for (std::size_t b = a + 1; b < m.mesh.vertices.size(); ++b)
      EXPECT_GE(distance(m.mesh.vertices[a], m.mesh.vertices[b]), 0.75 * options.spacing - 1e-9);
}

TEST(ElementMesh, SymmetryTheSkinLacksIsNotForced) {
  Ring star = star5();
  star[0] = star[0] * 1.5;  // one long point
  ElementMeshOptions options;
  options.gap = 6.0;
  options.spacing = 8.0;
  options.symmetry = 5;
  ElementMesh asked = buildElementMesh({filledShape(star)}, Region{Polygon{star, {}}}, options);
  options.symmetry = 1;
  ElementMesh plain = buildElementMesh({filledShape(star)}, Region{Polygon{star, {}}}, options);
  EXPECT_EQ(asked.symmetry, 1);
  ASSERT_EQ(asked.mesh.vertices.size(), plain.mesh.vertices.size());
  for (std::size_t v = 0; v < plain.mesh.vertices.size(); ++v) {
    EXPECT_EQ(asked.mesh.vertices[v].x, plain.mesh.vertices[v].x);
    EXPECT_EQ(asked.mesh.vertices[v].y, plain.mesh.vertices[v].y);
  }
}
