// Algorithm 1's streamlines: separated by at least s_stop, lengths within [s_min, s_max],
// inside the container and outside fixed elements, evenly spaced in a uniform field, and
// reproducible from a seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "flow/streamlines.hpp"
#include "pak/geom/closest_point.hpp"
#include "pak/geom/resample.hpp"

namespace pak {
namespace {

Ring circle(Vec2 c, double r, int n = 96) {
  Ring ring;
  for (int i = 0; i < n; ++i) ring.push_back(c + Vec2{r * std::cos(2 * M_PI * i / n), r * std::sin(2 * M_PI * i / n)});
  return ring;
}

struct TracingCase {
  VectorField field;
  StreamlineInput input;
  StreamlineOptions options;
};

// A disc swirling around its centre with a fixed disc off-centre.
TracingCase swirl() {
  TracingCase s;
  s.input.container = Region{Polygon{circle({100, 100}, 90), {}}};
  s.input.obstacles = Region{Polygon{circle({130, 100}, 15), {}}};
  Ring guide = circle({100, 100}, 85, 200);
  guide.push_back(guide.front());
  s.input.guides = {guide};
  VectorFieldOptions fo;
  fo.sampleSpacing = 1.0;
  fo.resolution = 96;
  s.field = buildVectorField(s.input.container, s.input.guides, fo);
  s.options.gap = 12;
  s.options.minLength = 20;
  s.options.maxLength = 120;
  s.options.sampleSpacing = 1.0;
  s.options.seed = 5;
  return s;
}

TEST(Streamlines, SeparatedBoundedInsideAndClearOfObstacles) {
  TracingCase s = swirl();
  std::vector<Polyline> lines = traceStreamlines(s.field, s.input, s.options);
  ASSERT_GE(lines.size(), 10u);
  const double stop = s.options.stopRatio * s.options.gap;
  const double step = 0.5 * s.options.sampleSpacing;
  for (std::size_t a = 0; a < lines.size(); ++a) {
    const double length = polylineLength(lines[a]);
    EXPECT_GE(length, s.options.minLength);
    EXPECT_LE(length, s.options.maxLength + 1e-9);
    for (Vec2 p : lines[a]) {
      EXPECT_TRUE(pointInRegion(p, s.input.container));
      EXPECT_FALSE(pointInRegion(p, s.input.obstacles));
    }
    // Separation, measured from every point of one line to the other polyline.
    for (std::size_t b = 0; b < lines.size(); ++b) {
      if (a == b) continue;
      for (Vec2 p : lines[a]) ASSERT_GE(closestPointOnPolyline(p, lines[b]).distance, stop - step) << a << " vs " << b;
    }
  }
}

TEST(Streamlines, FixedStreamlinesAreKeptClearOf) {
  TracingCase s = swirl();
  Polyline fixed{{40, 100}, {70, 100}};
  s.input.fixedStreamlines = {fixed};
  const double stop = s.options.stopRatio * s.options.gap;
  for (const Polyline& line : traceStreamlines(s.field, s.input, s.options))
    for (Vec2 p : line) EXPECT_GE(closestPointOnPolyline(p, fixed).distance, stop - 0.5 * s.options.sampleSpacing);
}

TEST(Streamlines, AUniformFieldGivesStraightEvenlySpacedLines) {
  TracingCase s;
  s.input.container = Region{Polygon{Ring{{0, 0}, {200, 0}, {200, 100}, {0, 100}}, {}}};
  s.input.guides = {{{0, 50}, {200, 50}}};
  VectorFieldOptions fo;
  fo.sampleSpacing = 2.0;
  fo.resolution = 64;
  s.field = buildVectorField(s.input.container, s.input.guides, fo);
  s.options.gap = 10;
  s.options.minLength = 50;
  s.options.maxLength = 400;
  s.options.sampleSpacing = 2.0;
  std::vector<Polyline> lines = traceStreamlines(s.field, s.input, s.options);
  ASSERT_GE(lines.size(), 8u);
  std::vector<double> ys;
  for (const Polyline& line : lines) {
    for (Vec2 p : line) EXPECT_NEAR(p.y, line.front().y, 1e-6);  // straight, horizontal
    ys.push_back(line.front().y);
  }
  std::sort(ys.begin(), ys.end());
  // Seeds on the left and right edges start lines anywhere, so neighbouring levels are less
  // than 2 s_gap apart (a wider space would have taken a seed s_gap from one of them), and the
  // walls are within s_gap of the outermost lines.
  ASSERT_GE(ys.size(), 6u);
  EXPECT_LT(ys.front(), s.options.gap);
  EXPECT_GT(ys.back(), 100.0 - s.options.gap);
  for (std::size_t k = 1; k < ys.size(); ++k) EXPECT_LT(ys[k] - ys[k - 1], 2.0 * s.options.gap) << ys[k - 1] << " to " << ys[k];
}

TEST(Streamlines, ASeedReproducesTheLinesAndAnotherSeedChangesThem) {
  TracingCase s = swirl();
  auto a = traceStreamlines(s.field, s.input, s.options);
  auto b = traceStreamlines(s.field, s.input, s.options);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k], b[k]);
  s.options.seed = 6;
  auto c = traceStreamlines(s.field, s.input, s.options);
  EXPECT_FALSE(c.size() == a.size() && c == a);
}

}  // namespace
}  // namespace pak
