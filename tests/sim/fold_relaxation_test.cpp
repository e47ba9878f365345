// The fold relaxation both simulators share (src/sim/fold_relaxation.hpp).
#include "sim/fold_relaxation.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace pak {
namespace {

// A unit square's corners, turned by 30°, doubled and moved: a similar copy of the rest shape.
std::vector<Vec2> similarCopy(const std::vector<Vec2>& rest) {
  const Vec2 turn{std::cos(std::numbers::pi / 6), std::sin(std::numbers::pi / 6)};
  std::vector<Vec2> out;
  for (Vec2 p : rest) out.push_back(Vec2{5.0, -3.0} + rotated(p * 2.0, turn));
  return out;
}

const std::vector<Vec2> kSquare{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(BlendTowardRest, TheRestShapeAtItsScaleIsAFixedPoint) {
  std::vector<Vec2> x = similarCopy(kSquare);
  const std::vector<Vec2> before = x;
  int moved = 0;
  blendTowardRest(x.data(), kSquare.data(), 4, 2.0, 0.0, Vec2{}, kInf, [&](int) { ++moved; });
  EXPECT_EQ(moved, 4);
  for (int v = 0; v < 4; ++v) EXPECT_LT(distance(x[v], before[v]), 1e-12);
}

TEST(BlendTowardRest, KeepZeroRestoresADisplacedCornerAndKeepAHalfGoesHalfway) {
  const std::vector<Vec2> fitted = similarCopy(kSquare);
  // Corners 0 and 2 pushed apart along their diagonal: the centre and the best-fit turn stay.
  const Vec2 centre = (fitted[0] + fitted[2]) * 0.5, push = (fitted[0] - centre) * 0.1;
  std::vector<Vec2> x = fitted;
  x[0] += push;
  x[2] -= push;
  std::vector<Vec2> half = x;
  blendTowardRest(x.data(), kSquare.data(), 4, 2.0, 0.0, Vec2{}, kInf, [](int) {});
  blendTowardRest(half.data(), kSquare.data(), 4, 2.0, 0.5, Vec2{}, kInf, [](int) {});
  for (int v = 0; v < 4; ++v) EXPECT_LT(distance(x[v], fitted[v]), 1e-12) << v;
  EXPECT_LT(distance(half[0], fitted[0] + push * 0.5), 1e-12);
  EXPECT_LT(distance(half[2], fitted[2] - push * 0.5), 1e-12);
}

TEST(BlendTowardRest, APatchMovesOnlyWhatIsWithinItsRadius) {
  std::vector<Vec2> x = similarCopy(kSquare);
  x[0] += Vec2{0.5, 0.0};
  const std::vector<Vec2> before = x;
  std::vector<int> moved;
  blendTowardRest(x.data(), kSquare.data(), 4, 2.0, 0.0, before[0], 1.0, [&](int v) { moved.push_back(v); });
  EXPECT_EQ(moved, std::vector<int>{0});
  for (int v = 1; v < 4; ++v) EXPECT_EQ(x[v], before[v]);
}

TEST(RelaxFold, WidensThePatchUntilTheFoldIsGoneThenStops) {
  std::vector<double> radii;
  int folds = 3;  // the fold lasts three steps
  const bool moved = relaxFold(
      10.0, [&]() -> std::optional<Vec2> { return folds-- > 0 ? std::optional<Vec2>(Vec2{}) : std::nullopt; },
      [&](double keep, Vec2, double radius) {
        EXPECT_EQ(keep, 0.25);
        radii.push_back(radius);
      });
  EXPECT_TRUE(moved);
  EXPECT_EQ(radii, (std::vector<double>{15.0, 20.0, 30.0}));
}

TEST(RelaxFold, EndsWithTheWholeRestShapeAndLeavesACleanMeshAlone) {
  std::vector<double> keeps;
  EXPECT_TRUE(relaxFold(
      10.0, []() -> std::optional<Vec2> { return Vec2{}; },
      [&](double keep, Vec2, double radius) { keeps.push_back(std::isinf(radius) ? keep : -1.0); }));
  EXPECT_EQ(keeps, (std::vector<double>{-1.0, -1.0, -1.0, -1.0, 0.5, 0.0}));
  EXPECT_FALSE(relaxFold(10.0, []() -> std::optional<Vec2> { return std::nullopt; }, [](double, Vec2, double) { FAIL(); }));
}

}  // namespace
}  // namespace pak
