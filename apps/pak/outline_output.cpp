#include "outline_output.hpp"

#include <cstdio>

namespace pak::cli {

SvgWriteOptions outlineWriteOptions(bool polyline, double tolerance, double canonicalScale) {
  SvgWriteOptions options;
  if (!polyline) options.curveTolerance = tolerance / canonicalScale;
  return options;
}

std::string polylineHelp(double tolerance) {
  char text[320];
  std::snprintf(text, sizeof text,
                "write outlines as polygons (the deformed points), not as cubic Béziers fitted within %g canonical "
                "units (curves to edit in Inkscape or Illustrator, smaller files); the report gives the point count "
                "and the fit's largest deviation",
                tolerance);
  return text;
}

void reportOutlines(nlohmann::json& report, bool polyline, const SvgPathStats& paths, double canonicalScale) {
  report["output-outlines"] = polyline ? "polygons" : "cubic Béziers";
  report["output-points"] = paths.points;  // every path's coordinate pairs, Bézier control points included
  report["output-largest-curve-deviation"] = paths.largestDeviation * canonicalScale;
  // The art drawn from input shapes (elements, fixed art): the points its input drew it with,
  // and the written points for each drawn one.
  report["drawn-points"] = paths.drawnPoints;
  report["output-points-per-drawn-point"] =
      paths.drawnPoints > 0 ? static_cast<double>(paths.pointsOfDrawnShapes) / static_cast<double>(paths.drawnPoints) : 0.0;
}

}  // namespace pak::cli
