#include "metrics_measure.hpp"

#include <cmath>

#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/io/json_syntax_error.hpp"
#include "pak/io/text_file.hpp"
#include "pak/metrics/metrics.hpp"
#include "report_fields.hpp"

namespace pak::cli {
namespace {

using nlohmann::json;

double negativeRatio(const PackingGeometry& packing) {
  double inside = area(intersect(unite(packing.elements), packing.container));
  return 1.0 - inside / area(packing.container);
}

json curveJson(const Curve& curve) { return {{"r", curve.r}, {"value", curve.value}}; }

}  // namespace

double gapFromReport(const json& report, const std::string& where) {
  if (!report.is_object()) throw InputError(where, "the report is not a JSON object");
  if (report.contains("d_gap") && report["d_gap"].is_number()) return report["d_gap"].get<double>();
  const json* gap = report.contains("parameters") && report["parameters"].is_object() &&
                            report["parameters"].contains("gap")
                        ? &report["parameters"]["gap"]
                        : nullptr;
  if (!gap || !gap->is_number() || !report.contains("canonical-scale") || !report["canonical-scale"].is_number())
    throw InputError(where, "the report has neither \"d_gap\" nor \"parameters\".\"gap\" with \"canonical-scale\"");
  double scale = report["canonical-scale"].get<double>();
  if (!(scale > 0.0) || !std::isfinite(scale)) throw InputError(where, "\"canonical-scale\" must be positive");
  return gap->get<double>() / scale;
}

json readReportFile(const std::string& path) {
  try {
    return json::parse(readTextFile(path));
  } catch (const json::exception& error) {
    throw jsonSyntaxError(path, error.what());
  }
}

std::vector<MeasuredPacking> measurePackings(std::vector<PackingGeometry>& packings, const MetricsArguments& args) {
  std::vector<MeasuredPacking> measured(packings.size());
  // Thesis 6.4: compare at the same negative-space ratio, here the packings' mean.
  if (args.calibrate && !packings.empty()) {
    double mean = 0.0;
    for (const PackingGeometry& p : packings) mean += negativeRatio(p);
    mean /= static_cast<double>(packings.size());
    for (std::size_t i = 0; i < packings.size(); ++i) {
      Calibration calibration = calibrateNegativeSpace(packings[i], mean);
      measured[i].calibrationOffset = calibration.offset;
      packings[i] = std::move(calibration.calibrated);
    }
  }
  // --grid is the evenness grid too: both rasterize the container's bounding square.
  EvennessOptions evenness;
  evenness.resolution = args.metrics.gridResolution;
  for (std::size_t i = 0; i < packings.size(); ++i) {
    measured[i].metrics = measurePacking(packings[i], args.metrics);
    measured[i].evenness = measureEvenness(packings[i], evenness);
  }
  return measured;
}

json packingJson(const MeasuredPacking& measured) {
  const PackingMetrics& m = measured.metrics;
  json out = {{"file", m.source},
              {"elements", m.elementCount},
              {"container-area", m.containerArea},
              {"positive-ratio", m.positiveRatio},
              {"negative-ratio", m.negativeRatio},
              {"d_gap", m.gap},
              {"d_gap-estimated", m.gapEstimated},
              {"Q-half-gap", m.contactAtHalfGap},
              {"O-half-gap", m.overlapAtHalfGap},
              {"largest-empty-radius", m.largestEmptyRadius},
              {"curves",
               {{"Q", curveJson(m.sphericalContact)},
                {"H", curveJson(m.distanceHistogram)},
                {"O", curveJson(m.overlap)},
                {"Q-grid", curveJson(m.gridSphericalContact)}}},
              {"histogram", {{"edges", m.binEdges}, {"density", m.binDensity}}}};
  out["calibration-offset"] = measured.calibrationOffset ? json(*measured.calibrationOffset) : json(nullptr);
  out["evenness"] = evennessJson(measured.evenness);
  return out;
}

}  // namespace pak::cli
