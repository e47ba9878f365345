// A guided element that leaves the container and comes back on the other side, one loop's
// shift away (thesis Fig. 5.17): it is not pulled in, the others pack around its part inside,
// and a frame shows it also one shift back and ahead, so frames side by side tile.
#include <gtest/gtest.h>

#include <algorithm>

#include "animation/animation_fixtures.hpp"
#include "pak/animation/animation.hpp"
#include "pak/error.hpp"
#include "pak/geom/verify.hpp"

namespace pak {
namespace {

constexpr double kShift = 600.0;  // the disc spans x ∈ [50, 450]: the runner's copies stay clear of it

// Eight spinning stars in the disc, and a runner that crosses it from the left, outside, to
// the right, outside, kShift further on.
AnimationScript travellingRunner() {
  AnimationScript script = test::spinningStars(8);
  AnimatedElementSpec runner;
  runner.id = "runner";
  runner.svg = "star.svg";
  runner.leavesContainer = true;
  runner.targets = {{0.0, {-20, 250}, {}, {}}, {0.5, {-20 + kShift / 2, 250}, {}, {}}, {1.0, {-20 + kShift, 250}, {}, {}}};
  script.elements.push_back(runner);
  return script;
}

Vec2 centreOf(const std::vector<Vec2>& points) {
  Vec2 c;
  for (Vec2 p : points) c += p;
  return c / static_cast<double>(points.size());
}

class TravellingElement : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    AnimationOptions options = test::quickAnimationOptions();
    options.stop.maxIterations = 300;
    options.initialScale = 0.5;  // in contact within the 300 iterations
    result = new AnimatedPacking(packAnimation(test::discScene(), {test::starElement("star.svg"), test::starElement("star.svg")},
                                               travellingRunner(), options));
  }
  static void TearDownTestSuite() { delete result; }
  static const AnimatedElement& runner() {
    return *std::find_if(result->elements.begin(), result->elements.end(), [](const AnimatedElement& e) { return e.guided; });
  }
  static AnimatedPacking* result;
};
AnimatedPacking* TravellingElement::result = nullptr;

TEST_F(TravellingElement, ItsSlicesOutsideStayOutsideOnTheirTargets) {
  const AnimatedElement& r = runner();
  ASSERT_TRUE(r.leavesContainer);
  const Vec2 first = centreOf(r.slices.front()), last = centreOf(r.slices.back());
  EXPECT_LT(distance(first, Vec2{-20, 250}), 15.0);
  EXPECT_LT(distance(last, Vec2{-20 + kShift, 250}), 15.0);
  // Wholly outside the disc, not pulled in by the boundary force, nor projected in at the end.
  for (const std::vector<Vec2>* slice : {&r.slices.front(), &r.slices.back()}) {
    int inside = 0;
    for (Vec2 p : *slice) inside += pointInRegion(p, result->container) ? 1 : 0;
    EXPECT_EQ(inside, 0);
  }
  // The loop joins the last slice to the first one moved by the shift, vertex by vertex.
  ASSERT_EQ(r.loopShift, (Vec2{kShift, 0.0}));
  for (std::size_t v = 0; v < r.slices.front().size(); ++v)
    ASSERT_LT(distance(r.slices.back()[v], r.slices.front()[v] + r.loopShift), 1e-9) << v;
  // It keeps its size outside as inside (the guided floor), instead of shrinking or ballooning.
  EXPECT_GE(smallestGuidedGrowthRatio(*result), 0.8 - 1e-9);
}

TEST_F(TravellingElement, TheOthersPackAroundItsPartInsideWithoutOverlapsInEveryFrame) {
  const double containerArea = area(result->container);
  PackingCheckOptions tolerance;
  tolerance.areaTolerance = 1e-4 * containerArea;
  const std::size_t count = result->elements.size();
  for (int k = 0; k < 16; ++k) {
    const double t = k / 16.0;
    const Packing frame = animationFrame(*result, t);
    const PackingCheck check = verifyPacking(checkedOutlines(frame), result->container, tolerance);
    EXPECT_EQ(check.overlappingPairs, 0) << "t = " << t;
    EXPECT_EQ(check.elementsOutside, 0) << "t = " << t;
    // The runner is drawn again one loop back and one ahead: a copy on each side.
    ASSERT_EQ(frame.elements.size(), count + 2);
    const std::size_t self = static_cast<std::size_t>(&runner() - result->elements.data());
    EXPECT_EQ(frame.elements[count].skin[0], (frame.elements[self].skin[0] - Vec2{kShift, 0.0}));
    EXPECT_EQ(frame.elements[count + 1].skin[0], (frame.elements[self].skin[0] + Vec2{kShift, 0.0}));
  }
  // Outside, the runner is no element of the packing: a frame's checks see nothing of it.
  EXPECT_TRUE(checkedOutlines(animationFrame(*result, 0.0))[&runner() - result->elements.data()].empty());
}

TEST(TravellingElementInput, ATargetOutsideOrATooShortTravelIsAnInputError) {
  const Library library{test::starElement("star.svg"), test::starElement("star.svg")};
  AnimationScript outside = travellingRunner();
  outside.elements.back().leavesContainer = false;
  EXPECT_THROW(packAnimation(test::discScene(), library, outside, test::quickAnimationOptions()), InputError);
  // Its copy one loop ahead would cross the disc while it is in it.
  AnimationScript shortTravel = travellingRunner();
  shortTravel.elements.back().targets = {{0.0, {-20, 250}, {}, {}}, {1.0, {380, 250}, {}, {}}};
  try {
    packAnimation(test::discScene(), library, shortTravel, test::quickAnimationOptions());
    ADD_FAILURE() << "a travel shorter than the container was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("copy one loop away"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace pak
