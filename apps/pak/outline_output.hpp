#pragma once
// How `pak pack`, `pak flow` and `pak animate` write their outlines: cubic Béziers fitted to
// the deformed polygons (one fitter, bezier_fit), or the polygons themselves (--polyline).
#include <string>

#include <nlohmann/json.hpp>

#include "pak/io/svg_writer.hpp"

namespace pak::cli {

// How far a written Bézier outline may stray from the deformed polygon (canonical units).
// FLOWPAK's bent elements are long and smooth; RepulsionPak's and AnimationPak's meshes hold
// the art's details closer (issue 17 asks ≤ 0.1; the fit and the measure each flatten within a
// few percent of the tolerance, so the measured deviation may run that much over it).
constexpr double kFlowCurveTolerance = 0.4;
constexpr double kMeshCurveTolerance = 0.085;

// Béziers within `tolerance` canonical units (`canonicalScale`: canonical units per input unit),
// or polygons.
SvgWriteOptions outlineWriteOptions(bool polyline, double tolerance, double canonicalScale);

// --polyline's help, naming the tolerance the command fits within.
std::string polylineHelp(double tolerance);

// The report's output-outlines, output-points and output-largest-curve-deviation (canonical).
void reportOutlines(nlohmann::json& report, bool polyline, const SvgPathStats& paths, double canonicalScale);

}  // namespace pak::cli
