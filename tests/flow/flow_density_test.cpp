// FLOWPAK's automatic density: known answers for the gap, lengths and spacing worked out from
// the wanted count, the free area and the elements' proportions, and the options' own values
// kept when given.
#include <gtest/gtest.h>

#include <cmath>

#include "flow/flow_density.hpp"
#include "pak/error.hpp"

namespace pak {
namespace {

TEST(FlowDensity, MedianAspectIsClampedAndSkipsNonsense) {
  EXPECT_DOUBLE_EQ(medianAspect({3.0, 5.0, 4.0}), 4.0);
  EXPECT_DOUBLE_EQ(medianAspect({3.0, 5.0, 4.0, 6.0}), 4.5);
  EXPECT_DOUBLE_EQ(medianAspect({0.2, 0.5}), 1.5);   // a round library still gets long streamlines
  EXPECT_DOUBLE_EQ(medianAspect({40.0}), 8.0);
  EXPECT_DOUBLE_EQ(medianAspect({}), 1.5);
  EXPECT_DOUBLE_EQ(medianAspect({NAN, 4.0, -1.0}), 4.0);
}

TEST(FlowDensity, TheGapPutsAboutTheWantedCountInTheFreeArea) {
  FlowOptions o;  // everything automatic
  const double area = 250000.0, aspect = 4.0;
  FlowDensity d = resolveDensity(o, area, aspect);
  // count elements of footprint k·a·g² fill the area: quadrupling the count halves the gap.
  o.count = 400;
  FlowDensity dense = resolveDensity(o, area, aspect);
  EXPECT_NEAR(dense.gap, 0.5 * d.gap, 1e-12);
  // The lengths and the spacing follow the gap, the lengths the aspect too.
  EXPECT_NEAR(dense.maxLength, 0.5 * d.maxLength, 1e-12);
  EXPECT_NEAR(dense.minLength, 0.5 * d.minLength, 1e-12);
  EXPECT_NEAR(dense.spacing, 0.5 * d.spacing, 1e-12);
  EXPECT_NEAR(resolveDensity(o, area, 2.0 * aspect).maxLength / dense.maxLength, std::sqrt(2.0), 1e-12);
  EXPECT_LT(d.minLength, d.maxLength);
  EXPECT_GT(d.maxLength, 2.0 * d.gap);  // longer than wide: streamlines, not dots
  EXPECT_GT(d.spacing, 0.0);
  EXPECT_LT(d.spacing, 0.25 * d.gap);
  // The bundled koi (free area 258,937, median aspect 4.27) gets a gap near 21, which gave it
  // about 100 elements when this was measured.
  EXPECT_NEAR(resolveDensity(FlowOptions{}, 258937.0, 4.27).gap, 21.3, 0.1);
}

TEST(FlowDensity, UnderAMirrorTheCountIsForBothHalves) {
  FlowOptions o;
  FlowDensity whole = resolveDensity(o, 100000.0, 3.0);
  o.mirror = MirrorLine::vertical(0.0);
  // Half the area packed for half the count: the same gap as the whole unmirrored.
  EXPECT_NEAR(resolveDensity(o, 50000.0, 3.0).gap, whole.gap, 1e-12);
}

TEST(FlowDensity, GivenValuesAreKept) {
  FlowOptions o;
  o.gap = 30.0;
  o.minLength = 45.0;
  o.maxLength = 180.0;
  o.spacing = 0.0;  // touching, as the thesis's blobs
  FlowDensity d = resolveDensity(o, 1e6, 4.0);
  EXPECT_EQ(d.gap, 30.0);
  EXPECT_EQ(d.minLength, 45.0);
  EXPECT_EQ(d.maxLength, 180.0);
  EXPECT_EQ(d.spacing, 0.0);
  // A given gap alone sets the lengths and spacing in proportion.
  FlowOptions gapOnly;
  gapOnly.gap = 30.0;
  FlowDensity g = resolveDensity(gapOnly, 1e6, 4.0);
  EXPECT_EQ(g.gap, 30.0);
  EXPECT_NEAR(g.maxLength / resolveDensity(gapOnly, 1.0, 4.0).maxLength, 1.0, 1e-12);  // the area no longer matters
}

TEST(FlowDensity, AnAutomaticLengthThatCrossesAGivenOneIsAnError) {
  FlowOptions o;
  o.gap = 20.0;
  o.minLength = 5000.0;  // longer than the automatic s_max
  EXPECT_THROW(resolveDensity(o, 1e5, 4.0), InputError);
}

}  // namespace
}  // namespace pak
