#include "flow/flow_density.hpp"

#include <algorithm>
#include <cmath>

#include "pak/error.hpp"

namespace pak {
namespace {

// A streamline field of gap g carries elements about g wide; one of aspect a then covers
// about kFootprint × a × g² of the free space with its blob. Measured on the bundled koi
// (113 elements at g = 20 with the lengths below; docs/flowpak.md, "Density").
constexpr double kFootprint = 1.34;
// Streamlines run from kMinLength to kMaxLength times a × g: elements are drawn at their own
// proportions or up to 40% longer, and a short stub is not worth an element.
constexpr double kMinLength = 0.35;
constexpr double kMaxLength = 1.4;
// The channels between elements: wide enough to read as negative space, narrow enough that
// the art fills (fill and pocket share against this ratio: docs/flowpak.md, "Density").
constexpr double kSpacingPerGap = 0.12;
// Aspects outside this range are clamped: a round element still gets streamlines longer
// than wide, and a hair-thin one no endless streamline.
constexpr double kAspectMin = 1.5, kAspectMax = 8.0;

}  // namespace

double medianAspect(const std::vector<double>& aspects) {
  std::vector<double> sorted;
  for (double a : aspects)
    if (std::isfinite(a) && a > 0.0) sorted.push_back(a);
  if (sorted.empty()) return kAspectMin;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  return std::clamp(median, kAspectMin, kAspectMax);
}

FlowDensity resolveDensity(const FlowOptions& options, double freeArea, double aspect) {
  FlowDensity d;
  const double wanted = options.mirror ? 0.5 * options.count : static_cast<double>(options.count);
  d.gap = options.gap > 0.0 ? options.gap : std::sqrt(freeArea / (kFootprint * aspect * wanted));
  d.minLength = options.minLength > 0.0 ? options.minLength : kMinLength * aspect * d.gap;
  d.maxLength = options.maxLength > 0.0 ? options.maxLength : kMaxLength * aspect * d.gap;
  d.spacing = options.spacing >= 0.0 ? options.spacing : kSpacingPerGap * d.gap;
  if (d.minLength > d.maxLength)
    throw InputError(options.minLength > 0.0 ? "--min-length" : "--max-length",
                     "the shortest streamline would be longer than the longest (" + std::to_string(d.minLength) +
                         " > " + std::to_string(d.maxLength) + " canonical units)");
  return d;
}

}  // namespace pak
