#include "pak/geom/best_fit_rotation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pak {
namespace {

TEST(BestFitRotation, RecoversTheTurnOfARotatedAndScaledShape) {
  const std::vector<Vec2> rest = {{-3, -1}, {4, -2}, {2, 3}, {-3, 0}};  // offsets about their mean
  for (double angle : {0.0, 0.5, 2.0, -2.9}) {
    BestFitRotation fit;
    for (Vec2 q : rest) fit.add(q, rotated(q, angle) * 1.7);
    const Vec2 turn = fit.turn();
    EXPECT_NEAR(turn.x, std::cos(angle), 1e-12) << angle;
    EXPECT_NEAR(turn.y, std::sin(angle), 1e-12) << angle;
  }
}

TEST(BestFitRotation, WeightsChooseWhichPairsCount) {
  BestFitRotation fit;  // the first pair turns by 90°, the second not at all, and weighs nothing
  fit.add({1, 0}, {0, 1}, 1.0);
  fit.add({1, 0}, {1, 0}, 0.0);
  EXPECT_NEAR(fit.turn().x, 0.0, 1e-15);
  EXPECT_NEAR(fit.turn().y, 1.0, 1e-15);
}

TEST(BestFitRotation, NoOffsetsGiveNoTurn) {
  BestFitRotation fit;
  fit.add({0, 0}, {3, 4});
  EXPECT_EQ(fit.turn(), (Vec2{1.0, 0.0}));
  EXPECT_EQ(rotated(Vec2{2, 5}, fit.turn()), (Vec2{2, 5}));
}

TEST(Vec2, RotatedByATurnMatchesRotatedByItsAngle) {
  const Vec2 a{3, -2};
  const Vec2 byTurn = rotated(a, Vec2{std::cos(0.7), std::sin(0.7)}), byAngle = rotated(a, 0.7);
  EXPECT_NEAR(byTurn.x, byAngle.x, 1e-14);
  EXPECT_NEAR(byTurn.y, byAngle.y, 1e-14);
}

}  // namespace
}  // namespace pak
